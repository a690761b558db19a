#pragma once
// The `rigidfold` subcommands. Each add_*_command registers one subcommand on the app;
// its callback does the work and throws rigidfold::InputError on bad input (main turns
// that into one line on stderr and exit status 2).
#include <CLI/CLI.hpp>

namespace rigidfold::cli {

// Builds the app with every subcommand, parses argv and runs the command. Returns the exit
// status: 0 success (every requested output exists), 2 bad input (CLI::ParseError,
// InputError, std::invalid_argument, and std::bad_alloc: out of memory), 3 no answer within
// tolerance (NoAnswerError: nothing written), 1 internal error (any other exception: a bug).
int run_cli(int argc, const char* const* argv);

void add_info_command(CLI::App& app);      // rigidfold info PATTERN.fold [--json]
void add_fold_command(CLI::App& app);      // rigidfold fold PATTERN.fold --angles A.json --out F.fold [--obj F.obj]
void add_check_command(CLI::App& app);     // rigidfold check PATTERN.fold [--ignore-assignment] [--json]
void add_vertex_command(CLI::App& app);    // rigidfold vertex s4r ...
void add_generate_command(CLI::App& app);  // rigidfold generate KIND ... --out P.fold
void add_report_command(CLI::App& app);    // rigidfold report DIR --out OUTDIR (main job)
void add_trace_command(CLI::App& app);
void add_string_command(CLI::App& app);   // rigidfold string forward|design ... (origami strings)
void add_import_command(CLI::App& app);   // rigidfold import CP.svg --out CP.fold (SVG crease pattern -> FOLD)
void add_export_command(CLI::App& app);   // rigidfold export P.fold --svg P.svg (crease pattern -> SVG in Origami Simulator colours)
void add_assignments_command(CLI::App& app);  // rigidfold assignments PATTERN [--json] [--list N]
void add_energy_command(CLI::App& app);  // rigidfold energy PATTERN --rest REST [--k-m K --k-v K] [--json]
void add_waterbomb_command(CLI::App& app);  // rigidfold waterbomb --n N --theta0-deg T [--k-ratio R | --k-m K --k-v K] [--json]
void add_thick_command(CLI::App& app);  // rigidfold thick PATTERN --thickness T [--hinges top|bottom|mid|valley|bennett] [--json] [--out THICK.fold] [--stl F.stl --at DEG]
void add_sorce_command(CLI::App& app);  // rigidfold sorce PATTERN --thickness T [--offsets linear|SPEC.json] [--optimize] [--json] [--out DIR]
void add_network_command(CLI::App& app);  // rigidfold network NETWORK.json [--json] [--trace N]
void add_metamaterial_command(CLI::App& app);  // rigidfold metamaterial --unit square-twist|element1|element2|element3 [...] [--json] [--plot DIR]
void add_repair_command(CLI::App& app);  // rigidfold repair PATTERN --out R.fold [--keep-boundary] [--fix V,...] [--max-move D] [--json]

}  // namespace rigidfold::cli
