#include "app/cli.h"

int main(int argc, char** argv) { return vplab::runCommandLine(argc, argv); }
