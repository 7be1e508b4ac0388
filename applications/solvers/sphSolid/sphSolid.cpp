// sphSolid: the one generic solver. Reads a case, loads the model libraries, builds every
// model by name and runs. See `sphSolid -help` and README.md.
//
// With -parallel (`mpirun -np N sphSolid -parallel`) MPI is open for the whole process; without
// it sphSolid is a serial program that never calls MPI (no mpirun needed).
#include "core/Application.hpp"
#include "parallel/Communicator.hpp"
#include "sphSolid/SolidApplication.hpp"

#include <iostream>
#include <optional>
#include <streambuf>
#include <string>

namespace
{

// Looked for before MPI is opened, so before the command line is parsed (sphSolidMain accepts
// and lists the option).
bool parallelRequested(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "-parallel" || arg == "--parallel")
        {
            return true;
        }
    }
    return false;
}

// A stream buffer that drops everything written to it.
class NullBuffer : public std::streambuf
{
protected:
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize count) override { return count; }
};

// The log is written once, by rank 0: on the other ranks std::cout goes nowhere while this
// object lives (restored on destruction, as std::cout is flushed again after main returns).
class QuietOutput
{
public:
    explicit QuietOutput(bool quiet) : saved_(quiet ? std::cout.rdbuf(&null_) : nullptr) {}
    ~QuietOutput()
    {
        if (saved_ != nullptr)
        {
            std::cout.rdbuf(saved_);
        }
    }
    QuietOutput(const QuietOutput&) = delete;
    QuietOutput& operator=(const QuietOutput&) = delete;

private:
    NullBuffer null_;
    std::streambuf* saved_;
};

// Rank 0 prints the errors every rank meets alike and all return their exit code; an error one
// rank meets alone is printed by that rank, with its number, and stops every rank.
sph::ErrorReporting rankReporting(const sph::Communicator& world)
{
    sph::ErrorReporting reporting;
    reporting.printsCollective = world.rank() == 0;
    reporting.alonePrefix = "[rank " + std::to_string(world.rank()) + "] ";
    reporting.stopAll = [world](int exitCode) { world.abort(exitCode); };
    return reporting;
}

int parallelMain(int argc, char** argv)
{
    // Kept until main returns: MPI_Finalize after the last rank's work and output.
    std::optional<sph::MpiSession> session;
    const int opened = sph::guardedMain([&] {
        session.emplace(argc, argv);
        return 0;
    });
    if (opened != 0)
    {
        return opened;
    }
    const sph::Communicator world = sph::Communicator::world();
    const QuietOutput quiet(world.rank() != 0);
    const int exitCode =
        sph::guardedMain([&] { return sph::sphSolidMain(argc, argv); }, rankReporting(world));
    // mpirun stops the whole job once a rank exits with a non-zero code: no rank leaves before
    // rank 0 has printed the collective error.
    world.barrier();
    return exitCode;
}

} // namespace

int main(int argc, char** argv)
{
    if (parallelRequested(argc, argv))
    {
        return parallelMain(argc, argv);
    }
    return sph::guardedMain([&] { return sph::sphSolidMain(argc, argv); });
}
