// The command line for course staff (issue 14): `vplab exercise` and `vplab grade numbers|image`,
// registered on the main CLI11 app by one call, each run from its subcommand's callback.
#pragma once

namespace CLI {
class App;
}

namespace vplab {

/// Adds the subcommands `exercise` and `grade` to the app. Their callbacks run the command and end
/// the parse with CLI::RuntimeError(exit code), which CLI::App::exit returns as the exit code:
/// 0 passed / written, 1 wrong (grade) or failed (exercise), 2 a usage or input error.
void addCourseCommands(CLI::App& app);

}  // namespace vplab
