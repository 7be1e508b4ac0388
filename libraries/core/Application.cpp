#include "Application.hpp"

#include "InputError.hpp"
#include "IoError.hpp"

#include <iostream>
#include <new>

namespace sph
{

namespace
{

// What escaped the body: the message (without the blank line before it) and how it ends.
struct Failure
{
    std::string message;
    int exitCode;
    bool collective;
};

// The failure of the exception being handled (called inside a catch block).
Failure currentFailure()
{
    const std::string banner = "--> " + InputError::programName();
    try
    {
        throw;
    }
    catch (const InputError& error)
    {
        return {error.what(), 1, true};
    }
    catch (const NumericalFailure& failure)
    {
        return {banner + " NUMERICAL FAILURE\n" + failure.what() + "\n", 2, true};
    }
    catch (const IoError& error)
    {
        return {banner + " FATAL I/O ERROR\n" + error.what() +
                    "\nThe files written before are intact: make room on the disk, raise the "
                    "file-size limit or make the folder writable, and run again; a solver run "
                    "continues with 'startFrom latestTime;', a study keeps its finished "
                    "variants.\n",
                4, true};
    }
    catch (const std::bad_alloc&)
    {
        return {banner + " FATAL ERROR\nout of memory (try fewer particles or a machine with more "
                         "memory)\n",
                3, false};
    }
    catch (const std::exception& error)
    {
        return {banner + " FATAL ERROR (internal)\n" + error.what() +
                    "\nThis is a bug in sphSolid or in a model library; please report it with "
                    "the case that triggers it.\n",
                3, false};
    }
    catch (...)
    {
        return {banner + " FATAL ERROR (internal)\nan unknown exception escaped; please report "
                         "it with the case that triggers it.\n",
                3, false};
    }
}

int report(const Failure& failure, const ErrorReporting& reporting)
{
    std::cout.flush();
    if (failure.collective)
    {
        if (reporting.printsCollective)
        {
            std::cerr << "\n" << failure.message << std::flush;
        }
        return failure.exitCode;
    }
    std::cerr << "\n" << reporting.alonePrefix << failure.message << std::flush;
    if (reporting.stopAll)
    {
        reporting.stopAll(failure.exitCode);
    }
    return failure.exitCode;
}

} // namespace

int guardedMain(const std::function<int()>& body, const ErrorReporting& reporting)
{
    try
    {
        return body();
    }
    catch (...)
    {
        return report(currentFailure(), reporting);
    }
}

} // namespace sph
