#pragma once
// The ranks of a distributed run (issue 14: `mpirun -np N sphSolid -parallel`), behind a small
// interface: nothing outside libraries/parallel includes mpi.h, and a serial run (no
// MpiSession) is a communicator of one rank, so every caller is written once for both.
//
// Reductions that decide the run (the time step: a minimum) are exact whatever the rank
// count, since min and max are; a sum of doubles is gathered to every rank and summed there in
// rank order, so every rank sees the same bits (not the serial order's bits: sums only
// report, e.g. energies).

#include <string>
#include <vector>

namespace sph
{

// MPI for the lifetime of the object: initialised in the constructor (MPI_THREAD_FUNNELED: only
// the thread that made it calls MPI, OpenMP threads compute in between) and finalised in the
// destructor. One per process, made by main() when the run is parallel.
class MpiSession
{
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    // Whether a session is open in this process.
    static bool active();
};

class Communicator
{
public:
    // All ranks of the run (MPI_COMM_WORLD) when an MpiSession is open, else this process alone.
    static Communicator world();

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool parallel() const { return size_ > 1; }

    double minimum(double value) const;
    double maximum(double value) const;
    // Element by element, in place (every rank gives the same count).
    void minimum(std::vector<double>& values) const;
    void maximum(std::vector<double>& values) const;
    long long sum(long long value) const;
    // Summed in rank order on every rank: the same bits everywhere.
    double sum(double value) const;
    void sum(std::vector<double>& values) const; // element by element, in place
    // Every rank's value, in rank order, on every rank.
    std::vector<double> gather(double value) const;
    // Every rank's values, rank after rank, on every rank (each rank gives the same count).
    std::vector<double> gather(const std::vector<double>& values) const;
    // Personalised all-to-all: toEach[r] goes to rank r; the result's [r] came from rank r
    // (the particles that migrate, the ghost values; MPI_Alltoallv). toEach has size() entries.
    std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& toEach) const;
    // The same when each rank already knows how many values it receives from each (a fixed
    // pattern, e.g. refreshing ghosts): point to point with those ranks only, no collective.
    std::vector<std::vector<double>> exchangeKnown(const std::vector<std::vector<double>>& toEach,
                                                   const std::vector<std::size_t>& fromEachCount) const;
    // Rank `root`'s text on every rank (e.g. the one diagnosis of a failure).
    std::string broadcast(const std::string& text, int root) const;
    void barrier() const;
    // Stops every rank with exitCode (MPI_Abort): for an error one rank met alone, which the
    // others would otherwise wait for forever. Without a session, this process exits (_Exit).
    [[noreturn]] void abort(int exitCode) const;

private:
    Communicator(int rank, int size) : rank_(rank), size_(size) {}
    int rank_;
    int size_;
};

} // namespace sph
