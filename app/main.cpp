// rigidfold: command-line front end. Exit status 0 on success, 2 on bad input.
#include <iostream>

#include "app/commands.hpp"
#include "kernel/pattern/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"rigidfold: exact kinematics of rigid origami"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rigidfold 0.1.0");
  rigidfold::cli::add_info_command(app);
  rigidfold::cli::add_fold_command(app);
  rigidfold::cli::add_check_command(app);
  rigidfold::cli::add_vertex_command(app);
  rigidfold::cli::add_generate_command(app);
  rigidfold::cli::add_report_command(app);
  rigidfold::cli::add_trace_command(app);
  rigidfold::cli::add_string_command(app);
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
  } catch (const rigidfold::InputError& e) {
    std::cerr << "rigidfold: error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "rigidfold: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rigidfold: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
