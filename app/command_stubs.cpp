// Temporary weak definitions so the CLI links while subcommands are being written.
// Each real command file overrides its stub. (Removed once all commands exist.)
#include "app/commands.hpp"

namespace rigidfold::cli {
__attribute__((weak)) void add_info_command(CLI::App&) {}
__attribute__((weak)) void add_fold_command(CLI::App&) {}
__attribute__((weak)) void add_vertex_command(CLI::App&) {}
__attribute__((weak)) void add_generate_command(CLI::App&) {}
__attribute__((weak)) void add_report_command(CLI::App&) {}
}  // namespace rigidfold::cli
