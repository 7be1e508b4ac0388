#pragma once
// One run per case folder (issue 31 item 11: two sphSolid in one case overwrote each other's
// output in silence). A run holds <case>/.sphSolid.lock, an advisory lock (flock) the system
// releases when the process ends however it ends; the file says who holds it: program, pid,
// host and start time. A second run refuses with that; a file left by a process that no longer
// runs (killed) is taken over with a line saying so. The file stays (emptied) after the run, so
// that no second run can lock a file being removed.

#include <filesystem>
#include <string>

namespace sph
{

class CaseLock
{
public:
    // Locks `caseDir` for `program` ("sphSolid"). InputError naming the holder when a live
    // process holds it; IoError when the lock file cannot be written.
    CaseLock(const std::filesystem::path& caseDir, const std::string& program);
    ~CaseLock();
    CaseLock(const CaseLock&) = delete;
    CaseLock& operator=(const CaseLock&) = delete;

    // "" or, when a dead process's lock was taken over, the line that says whose.
    const std::string& takenOver() const { return takenOver_; }

    static std::filesystem::path fileOf(const std::filesystem::path& caseDir)
    {
        return caseDir / ".sphSolid.lock";
    }

private:
    int fd_ = -1;
    std::string takenOver_;
};

// How many processes an MPI launcher started this one among (mpirun -np N sets it in each:
// Open MPI's OMPI_COMM_WORLD_SIZE, MPICH's and Slurm's PMI_SIZE); 1 when none did.
long launchedRanks();

} // namespace sph
