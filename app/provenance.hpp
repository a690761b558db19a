#pragma once
// Provenance of a command's JSON output: which rigidfold wrote it and how it
// was called, so that a result can be traced back and reproduced:
//   "provenance": {"rigidfold_version": "0.1.0", "rigidfold_commit": "178e3b3c0d1e",
//                  "command": "trace", "arguments": ["trace", "P.fold", "--steps", "30", "--json"],
//                  "options": {"pattern": "P.fold", "--steps": "30", "--json": true}}
// "arguments" is the command line after the program name, exactly as given; "options" holds
// the options and positionals that were given (values as typed; a flag is true); an option
// not given took its documented default in that version.
// run_cli() records the invocation before parsing; a command adds provenance_json() to each
// JSON document it prints or writes.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace rigidfold::cli {

// Remembers the parser and the raw arguments (argv[1..argc-1]) for provenance_json(), until
// forget_invocation() (run_cli calls both: the parser lives only as long as run_cli).
void record_invocation(const CLI::App& app, int argc, const char* const* argv);
void forget_invocation();

// The provenance object of the command being run (version and commit alone when no
// invocation was recorded, e.g. in library use).
nlohmann::ordered_json provenance_json();

// A copy of `document` (a JSON object) with "provenance": provenance_json() as its last key.
nlohmann::ordered_json with_provenance(nlohmann::ordered_json document);
nlohmann::json with_provenance(nlohmann::json document);

// The text a command prints or writes for `document`: with_provenance(document), indented by
// two spaces. Paths and arguments are bytes that need not be UTF-8, which JSON strings must
// be: such bytes are written as U+FFFD rather than failing after the files were written.
std::string document_text(const nlohmann::ordered_json& document);
std::string document_text(const nlohmann::json& document);

// "rigidfold 0.1.0 (commit ...)": the --version text.
std::string version_text();

}  // namespace rigidfold::cli
