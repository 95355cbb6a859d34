#pragma once
// Log lines on stderr. Under systemd (JOURNAL_STREAM set) each line starts with its syslog
// priority, "<3>" error .. "<6>" info, which journald turns into the entry's priority.
#include <string>

namespace penshape::daemon {

enum class LogLevel { kError = 3, kWarning = 4, kInfo = 6 };

void log(LogLevel level, const std::string& message);

} // namespace penshape::daemon
