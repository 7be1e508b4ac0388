#pragma once
// The top-level guard every application's main() runs in: whatever escapes becomes a clean
// message and an exit code, never an uncaught exception, abort or core dump.
//   InputError        -> the formatted message, exit 1
//   NumericalFailure  -> the diagnosis, exit 2 (the last good state was written before throwing)
//   IoError           -> the file and the system's reason, exit 4 (every output already in
//                        place is intact: io/AtomicFile)
//   anything else     -> "internal error" with what() and a request to report it, exit 3

#include <functional>
#include <stdexcept>
#include <string>

namespace sph
{

// A numerical blow-up (NaN, det F <= 0, crossing particles, time step collapse). The message
// names the step, time, particle and quantity.
class NumericalFailure : public std::runtime_error
{
public:
    explicit NumericalFailure(const std::string& message) : std::runtime_error(message) {}
};

int guardedMain(const std::function<int()>& body);

} // namespace sph
