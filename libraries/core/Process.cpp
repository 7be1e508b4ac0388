#include "core/Process.hpp"

#include "core/InputError.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <sstream>

extern char** environ;

namespace sph
{

namespace
{

volatile std::sig_atomic_t runningChild = 0; // the program runProgram waits for, 0: none
volatile std::sig_atomic_t stopSignal = 0;   // a stop signal forwardStopSignals() caught

extern "C" void forwardToChild(int signal)
{
    stopSignal = signal;
    if (runningChild > 0)
    {
        kill(static_cast<pid_t>(runningChild), signal); // async-signal-safe
    }
}

// After a forwarded stop signal: this process ends with it, as it would have without the
// handler (its parent sees it killed by that signal).
void endOnStopSignal()
{
    if (stopSignal != 0)
    {
        std::signal(stopSignal, SIG_DFL);
        std::raise(stopSignal);
    }
}

// The child's side of runProgram, between fork and exec: async-signal-safe calls only. On a
// failure, errno goes to `report` (closed on exec: nothing read means the program started).
[[noreturn]] void startChild(const char* executable, char* const* argv, const char* workingDir,
                             const char* log, pid_t parent, int report)
{
    setpgid(0, 0); // a Ctrl-C on the terminal reaches the parent only, which forwards it once
    prctl(PR_SET_PDEATHSIG, SIGTERM); // dies with the parent, even a parent killed by SIGKILL
    if (getppid() != parent)
    {
        _exit(127); // the parent died before prctl
    }
    int fd = -1;
    if ((workingDir[0] == '\0' || chdir(workingDir) == 0) &&
        (fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644)) >= 0 && dup2(fd, 1) >= 0 &&
        dup2(fd, 2) >= 0)
    {
        execve(executable, argv, environ);
    }
    const int error = errno;
    (void)!write(report, &error, sizeof error);
    _exit(127);
}

} // namespace

void forwardStopSignals()
{
    struct sigaction action {};
    action.sa_handler = forwardToChild;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (const int signal : {SIGTERM, SIGINT, SIGHUP})
    {
        sigaction(signal, &action, nullptr);
    }
}

int runProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
               const std::filesystem::path& log, const std::filesystem::path& workingDir,
               const std::string& hint)
{
    endOnStopSignal(); // stopped between two programs: the next one does not start
    std::vector<std::string> words{program.string()};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& word : words)
    {
        argv.push_back(word.data());
    }
    argv.push_back(nullptr);
    // The log path is made absolute first: the child opens it after changing folder.
    const std::string logPath = std::filesystem::absolute(log).string();
    const std::string executable = std::filesystem::absolute(program).string();
    const std::string folder = workingDir.string();
    int report[2];
    if (pipe2(report, O_CLOEXEC) != 0)
    {
        throw InputError("cannot start '" + program.string() + "': no pipe", {hint});
    }
    const pid_t parent = getpid();
    const pid_t child = fork();
    if (child == 0)
    {
        close(report[0]);
        startChild(executable.c_str(), argv.data(), folder.c_str(), logPath.c_str(), parent,
                   report[1]);
    }
    close(report[1]);
    if (child < 0)
    {
        close(report[0]);
        throw InputError("cannot start '" + program.string() + "'", {hint});
    }
    runningChild = child;
    int error = 0;
    ssize_t got = 0;
    while ((got = read(report[0], &error, sizeof error)) < 0 && errno == EINTR)
    {
    }
    close(report[0]);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR)
    {
    }
    runningChild = 0;
    if (got > 0)
    {
        throw InputError("cannot start '" + program.string() + "'", {hint});
    }
    endOnStopSignal();
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::optional<std::filesystem::path> findInPath(const std::string& name)
{
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':'))
    {
        const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / name;
        if (access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate))
        {
            return candidate;
        }
    }
    return std::nullopt;
}

} // namespace sph
