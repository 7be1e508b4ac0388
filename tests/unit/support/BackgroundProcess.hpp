#pragma once
// An application of build/bin running in the background while a test acts on it (signals, a
// second run beside it); killed if the test leaves it running.

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sph::test
{

class BackgroundProcess
{
public:
    // Starts build/bin/<app> with `args`, its output (stdout and stderr) in `log`.
    BackgroundProcess(const std::string& app, const std::vector<std::string>& args,
                      const std::filesystem::path& log);
    ~BackgroundProcess();
    BackgroundProcess(const BackgroundProcess&) = delete;
    BackgroundProcess& operator=(const BackgroundProcess&) = delete;

    pid_t pid() const { return pid_; }
    bool running() const;
    void signal(int number) const;
    // The wait status once it ends (at most 60 s, then the test fails).
    int wait();

private:
    pid_t pid_ = -1;
};

// The processes whose parent is `parent` (from /proc).
std::vector<pid_t> childrenOf(pid_t parent);

// Whether process `pid` exists and is not a zombie.
bool alive(pid_t pid);

} // namespace sph::test
