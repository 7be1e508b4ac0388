#include "support/BackgroundProcess.hpp"

#include "support/CaseRunner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace sph::test
{

namespace
{

// Fields of /proc/<pid>/stat after the command name: state, parent, ...
std::vector<std::string> statusFields(pid_t pid)
{
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    std::getline(in, text);
    const auto close = text.rfind(')');
    std::vector<std::string> fields;
    if (close == std::string::npos)
    {
        return fields;
    }
    std::istringstream words(text.substr(close + 1));
    for (std::string word; words >> word;)
    {
        fields.push_back(word);
    }
    return fields;
}

} // namespace

BackgroundProcess::BackgroundProcess(const std::string& app, const std::vector<std::string>& args,
                                     const std::filesystem::path& log)
{
    const std::string binary = (buildDir() / "bin" / app).string();
    std::vector<std::string> words{binary};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& word : words)
    {
        argv.push_back(word.data());
    }
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    REQUIRE(posix_spawn(&pid_, binary.c_str(), &actions, nullptr, argv.data(), environ) == 0);
    posix_spawn_file_actions_destroy(&actions);
}

BackgroundProcess::~BackgroundProcess()
{
    if (pid_ > 0)
    {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
    }
}

bool BackgroundProcess::running() const
{
    return waitpid(pid_, nullptr, WNOHANG) == 0;
}

void BackgroundProcess::signal(int number) const
{
    REQUIRE(kill(pid_, number) == 0);
}

int BackgroundProcess::wait()
{
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    int status = 0;
    while (waitpid(pid_, &status, WNOHANG) == 0)
    {
        if (std::chrono::steady_clock::now() > deadline)
        {
            FAIL("the process did not end within 60 s");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    pid_ = -1;
    return status;
}

std::vector<pid_t> childrenOf(pid_t parent)
{
    std::vector<pid_t> children;
    for (const auto& entry : std::filesystem::directory_iterator("/proc"))
    {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos)
        {
            continue;
        }
        const pid_t pid = static_cast<pid_t>(std::stol(name));
        const auto fields = statusFields(pid);
        if (fields.size() > 1 && std::stol(fields[1]) == parent)
        {
            children.push_back(pid);
        }
    }
    return children;
}

bool alive(pid_t pid)
{
    const auto fields = statusFields(pid);
    return !fields.empty() && fields[0] != "Z" && fields[0] != "X";
}

} // namespace sph::test
