#include "app/commands/cli.h"

int main(int argc, char** argv) { return vplab::runCommandLine(argc, argv); }
