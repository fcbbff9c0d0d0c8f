// Minimal leveled logging to stderr; the CLI's --quiet and tests lower the level.
#pragma once

#include <string_view>

namespace wavelit::util {

enum class LogLevel { Debug, Info, Warning, Error, Silent };

void setLogLevel(LogLevel level);
LogLevel logLevel();
void log(LogLevel level, std::string_view message);

inline void logInfo(std::string_view m) { log(LogLevel::Info, m); }
inline void logWarning(std::string_view m) { log(LogLevel::Warning, m); }
inline void logError(std::string_view m) { log(LogLevel::Error, m); }

} // namespace wavelit::util
