#include "app/provenance.hpp"

#include <string>
#include <vector>

#include "rigidfold_version.hpp"

namespace rigidfold::cli {
namespace {

struct Invocation {
  const CLI::App* app = nullptr;
  std::vector<std::string> arguments;
};

Invocation& invocation() {
  static Invocation recorded;
  return recorded;
}

// The options given to `app` and, recursively, to its parsed subcommands ("string design").
void add_given_options(const CLI::App& app, nlohmann::ordered_json& command, nlohmann::ordered_json& options) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0 || opt->get_name() == "--help" || opt->get_name() == "--version") continue;
    const std::vector<std::string>& given = opt->results();
    if (opt->get_expected_max() == 0)
      options[opt->get_name()] = true;
    else if (given.size() == 1)
      options[opt->get_name()] = given.front();
    else
      options[opt->get_name()] = given;
  }
  for (const CLI::App* sub : app.get_subcommands()) {
    const std::string name = command.is_string() ? command.get<std::string>() + " " + sub->get_name() : sub->get_name();
    command = name;
    add_given_options(*sub, command, options);
  }
}

}  // namespace

void record_invocation(const CLI::App& app, int argc, const char* const* argv) {
  Invocation& rec = invocation();
  rec.app = &app;
  rec.arguments.clear();
  for (int i = 1; i < argc; ++i) rec.arguments.emplace_back(argv[i] ? argv[i] : "");
}

void forget_invocation() { invocation() = Invocation{}; }

nlohmann::ordered_json provenance_json() {
  nlohmann::ordered_json j;
  j["rigidfold_version"] = kRigidfoldVersion;
  j["rigidfold_commit"] = kRigidfoldCommit;
  const Invocation& rec = invocation();
  if (!rec.app) return j;
  nlohmann::ordered_json command;  // null until a subcommand is found
  nlohmann::ordered_json options = nlohmann::ordered_json::object();
  add_given_options(*rec.app, command, options);
  j["command"] = command;
  j["arguments"] = rec.arguments;
  j["options"] = options;
  return j;
}

nlohmann::ordered_json with_provenance(nlohmann::ordered_json document) {
  document["provenance"] = provenance_json();
  return document;
}

nlohmann::json with_provenance(nlohmann::json document) {
  // nlohmann::json keeps its keys sorted, so the position is the sorted one there.
  document["provenance"] = nlohmann::json(provenance_json());
  return document;
}

std::string version_text() { return std::string("rigidfold ") + kRigidfoldVersion + " (commit " + kRigidfoldCommit + ")"; }

std::string document_text(const nlohmann::ordered_json& document) {
  return with_provenance(document).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string document_text(const nlohmann::json& document) {
  return with_provenance(document).dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace rigidfold::cli
