#include "solver/StopRequest.hpp"

#include "core/CaseDictionaries.hpp"
#include "core/InputError.hpp"
#include "solver/CaseSettings.hpp"

#include <csignal>

namespace sph
{

namespace
{

volatile std::sig_atomic_t caughtSignal = 0;

extern "C" void onStopSignal(int signal)
{
    if (caughtSignal != 0)
    {
        // The second signal: the default action (termination) as soon as this handler returns
        // (the signal is blocked while it runs). signal() and raise() are async-signal-safe.
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    caughtSignal = signal;
}

} // namespace

StopSignals::StopSignals()
{
    caughtSignal = 0;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGTERM);
    sigaddset(&action.sa_mask, SIGINT);
    action.sa_flags = SA_RESTART; // system calls under way (writing output) go on
    sigaction(SIGTERM, &action, &previousTerm_);
    sigaction(SIGINT, &action, &previousInt_);
}

StopSignals::~StopSignals()
{
    sigaction(SIGTERM, &previousTerm_, nullptr);
    sigaction(SIGINT, &previousInt_, nullptr);
}

int StopSignals::caught()
{
    return caughtSignal;
}

std::string StopSignals::name(int signal)
{
    switch (signal)
    {
    case SIGTERM:
        return "SIGTERM";
    case SIGINT:
        return "SIGINT";
    default:
        return "signal " + std::to_string(signal);
    }
}

std::string StopCode::describe(int code)
{
    return code == writeNow ? "stopAt writeNow" : StopSignals::name(code);
}

ControlDictWatch::ControlDictWatch(std::filesystem::path caseDir, bool writeNow,
                                   double checkSeconds)
    : caseDir_(std::move(caseDir)), writeNow_(writeNow), interval_(checkSeconds),
      lastCheck_(Clock::now()), stamp_(stamp())
{
}

std::optional<std::filesystem::file_time_type> ControlDictWatch::stamp() const
{
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(caseDir_ / "system" / "controlDict", ec);
    return ec ? std::nullopt : std::optional<std::filesystem::file_time_type>(time);
}

bool ControlDictWatch::writeNow(const std::function<void(const std::string&)>& report)
{
    const auto now = Clock::now();
    if (now - lastCheck_ < interval_)
    {
        return writeNow_;
    }
    lastCheck_ = now;
    const auto current = stamp();
    if (current == stamp_)
    {
        return writeNow_;
    }
    stamp_ = current;
    try
    {
        CaseDictionaries dicts(caseDir_);
        dicts.read({"controlDict"});
        writeNow_ = ControlSettings::read(dicts).stopAtWriteNow;
    }
    catch (const InputError& error)
    {
        report("--> " + InputError::programName() + " WARNING: system/controlDict changed but " +
               "is not valid: the run goes on (stopAt " + (writeNow_ ? "writeNow" : "endTime") +
               ")\n" + formatDiagnostic(error.where(), error.message(), error.notes()));
    }
    return writeNow_;
}

} // namespace sph
