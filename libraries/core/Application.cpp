#include "Application.hpp"

#include "InputError.hpp"
#include "IoError.hpp"

#include <iostream>
#include <new>

namespace sph
{

int guardedMain(const std::function<int()>& body)
{
    try
    {
        return body();
    }
    catch (const InputError& error)
    {
        std::cout.flush();
        std::cerr << "\n" << error.what() << std::flush;
        return 1;
    }
    catch (const NumericalFailure& failure)
    {
        std::cout.flush();
        std::cerr << "\n--> " << InputError::programName() << " NUMERICAL FAILURE\n"
                  << failure.what() << "\n"
                  << std::flush;
        return 2;
    }
    catch (const IoError& error)
    {
        std::cout.flush();
        std::cerr << "\n--> " << InputError::programName() << " FATAL I/O ERROR\n"
                  << error.what()
                  << "\nThe files written before are intact: make room on the disk, raise the "
                     "file-size limit or make the folder writable, and run again; a solver run "
                     "continues with 'startFrom latestTime;', a study keeps its finished "
                     "variants.\n"
                  << std::flush;
        return 4;
    }
    catch (const std::bad_alloc&)
    {
        std::cout.flush();
        std::cerr << "\n--> " << InputError::programName()
                  << " FATAL ERROR\nout of memory (try fewer particles or a machine with more "
                     "memory)\n"
                  << std::flush;
        return 3;
    }
    catch (const std::exception& error)
    {
        std::cout.flush();
        std::cerr << "\n--> " << InputError::programName() << " FATAL ERROR (internal)\n"
                  << error.what()
                  << "\nThis is a bug in sphSolid or in a model library; please report it with "
                     "the case that triggers it.\n"
                  << std::flush;
        return 3;
    }
    catch (...)
    {
        std::cout.flush();
        std::cerr << "\n--> " << InputError::programName()
                  << " FATAL ERROR (internal)\nan unknown exception escaped; please report it "
                     "with the case that triggers it.\n"
                  << std::flush;
        return 3;
    }
}

} // namespace sph
