#pragma once
// Bad user input (scene or sweep files, command-line arguments): exit code 2 (docs/design.md §6.2).
// Each message reads `FILE: /json/pointer: rule broken`; what() is all of them, one per line.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace wirepack::sweep {

class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<std::string> messages)
      : std::runtime_error(join(messages)), messages_(std::move(messages)) {}
  explicit InputError(const std::string& message) : InputError(std::vector<std::string>{message}) {}

  // Every error found, in the order found.
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  static std::string join(const std::vector<std::string>& messages) {
    std::string out;
    for (const auto& m : messages) {
      if (!out.empty()) out += '\n';
      out += m;
    }
    return out;
  }
  std::vector<std::string> messages_;
};

}  // namespace wirepack::sweep
