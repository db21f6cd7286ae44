#pragma once
// Strict reading of JSON input files (scene and sweep files).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/errors.hpp"

namespace wirepack::sweep {

// JSON pointer of `key` inside the object at `parent` ("" is the root), with RFC 6901
// escaping (~ -> ~0, / -> ~1).
std::string pointer_child(const std::string& parent, const std::string& key);

// Parses JSON text. Beyond nlohmann's parser this rejects duplicate keys and numbers that
// overflow a double (1e999), each reported with its JSON pointer. Throws InputError with
// messages `SOURCE: line L, column C: ...` (syntax) or `SOURCE: /pointer: ...`.
// With `soft_errors`, duplicate keys (which leave a usable document: the last value wins) are
// appended there instead of thrown, so a caller can report them with its own checks.
nlohmann::json parse_json_text(const std::string& text, const std::string& source,
                               std::vector<std::string>* soft_errors = nullptr);

// Reads and parses a file (see parse_json_text); an unreadable file is an InputError too.
nlohmann::json load_json_file(const std::string& path,
                              std::vector<std::string>* soft_errors = nullptr);

// Short description of an offending value for error messages (long values are cut).
std::string describe_value(const nlohmann::json& v);

// Loads `path` strictly and parses it with `parse(json, path)`; problems of the file itself
// (duplicate keys) are reported together with the parser's in one InputError.
template <class Parse>
auto load_and_parse(const std::string& path, Parse parse) {
  std::vector<std::string> errors;
  const nlohmann::json j = load_json_file(path, &errors);
  try {
    auto parsed = parse(j, path);
    if (errors.empty()) return parsed;
  } catch (const InputError& e) {
    errors.insert(errors.end(), e.messages().begin(), e.messages().end());
  }
  throw InputError(errors);
}

}  // namespace wirepack::sweep
