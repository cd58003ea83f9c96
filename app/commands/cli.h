// The `vplab` command line (CLI11): the viewer (no subcommand), `dump`, `render` and `bench`.
#pragma once

namespace vplab {

/// Parses the arguments, runs the command, returns the process exit code. Errors go to stderr.
int runCommandLine(int argc, char** argv);

}  // namespace vplab
