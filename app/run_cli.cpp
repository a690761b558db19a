#include <iostream>
#include <new>

#include "app/commands.hpp"
#include "app/number_flags.hpp"
#include "app/provenance.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold::cli {

int run_cli(int argc, const char* const* argv) {
  CLI::App app{"rigidfold: exact kinematics of rigid origami"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text());
  // In the order `rigidfold --help` lists them.
  for (void (*add)(CLI::App&) : {&add_info_command, &add_fold_command, &add_check_command, &add_vertex_command,
                                 &add_generate_command, &add_report_command, &add_trace_command, &add_string_command,
                                 &add_import_command, &add_export_command, &add_assignments_command, &add_energy_command,
                                 &add_waterbomb_command, &add_thick_command, &add_sorce_command, &add_network_command,
                                 &add_metamaterial_command, &add_repair_command})
    add(app);
  // No floating-point flag of any command takes NaN or +-inf (app/number_flags.hpp).
  require_finite_numbers(app);
  record_invocation(app, argc, argv);
  struct ForgetInvocation {
    ~ForgetInvocation() { forget_invocation(); }
  } forget_at_return;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "rigidfold: error: " << e.what() << "\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "rigidfold: error: " << e.what() << "\n";
    return 2;
  } catch (const NoAnswerError& e) {
    // The message states the residual it reached; no output was written.
    std::cerr << "rigidfold: no answer within tolerance: " << e.what() << "\n";
    return 3;
  } catch (const std::invalid_argument& e) {
    std::cerr << "rigidfold: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    // Sizes are checked against the documented limits (kernel/pattern/input_limits.hpp)
    // before allocating; this is an input within them that still needs more memory than
    // the process may have (ulimit -v).
    std::cerr << "rigidfold: error: out of memory: the input is too large for the memory available to this process\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rigidfold: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace rigidfold::cli
