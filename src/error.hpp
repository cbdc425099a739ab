#pragma once
// Errors the user can act on. Each carries the <sysexits.h> code the command exits with:
// 64 usage, 65 bad data, 66 missing input, 73 cannot create output, 78 bad configuration,
// 130 interrupted. Messages name the file, line, key and value at fault and what is allowed.
#include <sysexits.h>

#include <stdexcept>
#include <string>

namespace rollspec {

constexpr int kExitInterrupted = 130;

class UserError : public std::runtime_error {
 public:
  UserError(int exit_code, const std::string& message) : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

// Input echoed in a message, cut to about 200 characters: a 1 MB key or a 50 MB cell must not flood
// the terminal.
inline std::string clip(const std::string& s, std::size_t limit = 200) {
  if (s.size() <= limit) return s;
  return s.substr(0, limit) + "... (" + std::to_string(s.size()) + " bytes in all)";
}

inline UserError config_error(const std::string& m) { return UserError(EX_CONFIG, m); }
inline UserError data_error(const std::string& m) { return UserError(EX_DATAERR, m); }
inline UserError missing_input(const std::string& m) { return UserError(EX_NOINPUT, m); }
inline UserError cannot_create(const std::string& m) { return UserError(EX_CANTCREAT, m); }
inline UserError usage_error(const std::string& m) { return UserError(EX_USAGE, m); }

}  // namespace rollspec
