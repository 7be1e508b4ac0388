#include "parallel/Communicator.hpp"

#include <mpi.h>

#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace sph
{

namespace
{
bool sessionOpen = false;

void check(int status, const char* what)
{
    if (status != MPI_SUCCESS)
    {
        throw std::runtime_error(std::string("MPI: ") + what + " failed");
    }
}

// One value combined over the ranks by op (min and max are exact in any order).
double allReduce(double value, MPI_Op op)
{
    double result = value;
    check(MPI_Allreduce(&value, &result, 1, MPI_DOUBLE, op, MPI_COMM_WORLD), "MPI_Allreduce");
    return result;
}

// Each element combined over the ranks by op, in place.
void allReduce(std::vector<double>& values, MPI_Op op)
{
    check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE,
                        op, MPI_COMM_WORLD),
          "MPI_Allreduce");
}
} // namespace

MpiSession::MpiSession(int& argc, char**& argv)
{
    if (sessionOpen)
    {
        throw std::logic_error("MpiSession: MPI is already initialised in this process");
    }
    int provided = MPI_THREAD_SINGLE;
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    if (provided < MPI_THREAD_FUNNELED)
    {
        MPI_Finalize();
        throw std::runtime_error("MPI: this MPI library cannot be called from a program that "
                                 "also runs OpenMP threads (MPI_THREAD_FUNNELED not provided)");
    }
    sessionOpen = true;
}

MpiSession::~MpiSession()
{
    sessionOpen = false;
    MPI_Finalize();
}

bool MpiSession::active() { return sessionOpen; }

Communicator Communicator::world()
{
    if (!sessionOpen)
    {
        return {0, 1};
    }
    int rank = 0;
    int size = 1;
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &size), "MPI_Comm_size");
    return {rank, size};
}

double Communicator::minimum(double value) const
{
    return parallel() ? allReduce(value, MPI_MIN) : value;
}

double Communicator::maximum(double value) const
{
    return parallel() ? allReduce(value, MPI_MAX) : value;
}

void Communicator::minimum(std::vector<double>& values) const
{
    if (parallel())
    {
        allReduce(values, MPI_MIN);
    }
}

void Communicator::maximum(std::vector<double>& values) const
{
    if (parallel())
    {
        allReduce(values, MPI_MAX);
    }
}

long long Communicator::sum(long long value) const
{
    if (!parallel())
    {
        return value;
    }
    long long result = value;
    check(MPI_Allreduce(&value, &result, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD),
          "MPI_Allreduce");
    return result;
}

std::vector<double> Communicator::gather(double value) const
{
    std::vector<double> values(static_cast<std::size_t>(size_), value);
    if (parallel())
    {
        check(MPI_Allgather(&value, 1, MPI_DOUBLE, values.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD),
              "MPI_Allgather");
    }
    return values;
}

std::vector<double> Communicator::gather(const std::vector<double>& values) const
{
    if (!parallel())
    {
        return values;
    }
    std::vector<double> all(values.size() * static_cast<std::size_t>(size_));
    check(MPI_Allgather(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(),
                        static_cast<int>(values.size()), MPI_DOUBLE, MPI_COMM_WORLD),
          "MPI_Allgather");
    return all;
}

std::vector<std::vector<double>>
Communicator::exchangeKnown(const std::vector<std::vector<double>>& toEach,
                            const std::vector<std::size_t>& fromEachCount) const
{
    const auto ranks = static_cast<std::size_t>(size_);
    if (toEach.size() != ranks || fromEachCount.size() != ranks)
    {
        throw std::logic_error("Communicator::exchangeKnown: one buffer and count per rank expected");
    }
    if (!parallel())
    {
        return toEach;
    }
    // Point to point with the ranks that send or receive anything: no collective, so the cost
    // grows with the neighbours, not with the ranks.
    std::vector<std::vector<double>> fromEach(ranks);
    std::vector<MPI_Request> requests;
    for (std::size_t r = 0; r < ranks; ++r)
    {
        if (fromEachCount[r] > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
            toEach[r].size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        {
            throw std::length_error("Communicator::exchangeKnown: over 2^31 values for one rank");
        }
        if (r == static_cast<std::size_t>(rank_))
        {
            fromEach[r] = toEach[r];
            continue;
        }
        if (fromEachCount[r] > 0)
        {
            fromEach[r].resize(fromEachCount[r]);
            requests.emplace_back();
            check(MPI_Irecv(fromEach[r].data(), static_cast<int>(fromEachCount[r]), MPI_DOUBLE,
                            static_cast<int>(r), 0, MPI_COMM_WORLD, &requests.back()),
                  "MPI_Irecv");
        }
    }
    for (std::size_t r = 0; r < ranks; ++r)
    {
        if (r != static_cast<std::size_t>(rank_) && !toEach[r].empty())
        {
            requests.emplace_back();
            check(MPI_Isend(toEach[r].data(), static_cast<int>(toEach[r].size()), MPI_DOUBLE,
                            static_cast<int>(r), 0, MPI_COMM_WORLD, &requests.back()),
                  "MPI_Isend");
        }
    }
    check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
          "MPI_Waitall");
    return fromEach;
}

std::vector<std::vector<double>>
Communicator::exchange(const std::vector<std::vector<double>>& toEach) const
{
    if (toEach.size() != static_cast<std::size_t>(size_))
    {
        throw std::logic_error("Communicator::exchange: one buffer per rank expected");
    }
    if (!parallel())
    {
        return toEach;
    }
    // The counts first (each rank learns what it receives), then the values in one call.
    const auto ranks = static_cast<std::size_t>(size_);
    std::vector<int> sendCounts(ranks), receiveCounts(ranks), sendOffsets(ranks), receiveOffsets(ranks);
    for (std::size_t r = 0; r < ranks; ++r)
    {
        if (toEach[r].size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        {
            throw std::length_error("Communicator::exchange: over 2^31 values for one rank");
        }
        sendCounts[r] = static_cast<int>(toEach[r].size());
    }
    check(MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT,
                       MPI_COMM_WORLD),
          "MPI_Alltoall");
    std::vector<double> sendBuffer;
    std::size_t sendTotal = 0, receiveTotal = 0;
    for (std::size_t r = 0; r < ranks; ++r)
    {
        sendTotal += toEach[r].size();
        receiveTotal += static_cast<std::size_t>(receiveCounts[r]);
    }
    if (sendTotal > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
        receiveTotal > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    {
        throw std::length_error("Communicator::exchange: over 2^31 values in one exchange");
    }
    sendBuffer.reserve(sendTotal);
    for (std::size_t r = 0; r < ranks; ++r)
    {
        sendOffsets[r] = static_cast<int>(sendBuffer.size());
        sendBuffer.insert(sendBuffer.end(), toEach[r].begin(), toEach[r].end());
    }
    int offset = 0;
    for (std::size_t r = 0; r < ranks; ++r)
    {
        receiveOffsets[r] = offset;
        offset += receiveCounts[r];
    }
    std::vector<double> receiveBuffer(receiveTotal);
    check(MPI_Alltoallv(sendBuffer.data(), sendCounts.data(), sendOffsets.data(), MPI_DOUBLE,
                        receiveBuffer.data(), receiveCounts.data(), receiveOffsets.data(),
                        MPI_DOUBLE, MPI_COMM_WORLD),
          "MPI_Alltoallv");
    std::vector<std::vector<double>> fromEach(ranks);
    for (std::size_t r = 0; r < ranks; ++r)
    {
        const auto first = receiveBuffer.begin() + receiveOffsets[r];
        fromEach[r].assign(first, first + receiveCounts[r]);
    }
    return fromEach;
}

double Communicator::sum(double value) const
{
    if (!parallel())
    {
        return value;
    }
    std::vector<double> values{value};
    sum(values);
    return values[0];
}

void Communicator::sum(std::vector<double>& values) const
{
    if (!parallel())
    {
        return;
    }
    // MPI_Allreduce may sum in any order (and differently on different ranks): gather instead,
    // and add in rank order.
    const std::vector<double> all = gather(values);
    const std::size_t n = values.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        double total = 0.0;
        for (std::size_t r = 0; r < static_cast<std::size_t>(size_); ++r)
        {
            total += all[r * n + i];
        }
        values[i] = total;
    }
}

std::string Communicator::broadcast(const std::string& text, int root) const
{
    if (!parallel())
    {
        return text;
    }
    unsigned long long length = text.size();
    check(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, root, MPI_COMM_WORLD), "MPI_Bcast");
    std::string result = rank_ == root ? text : std::string(length, '\0');
    if (length > 0)
    {
        check(MPI_Bcast(result.data(), static_cast<int>(length), MPI_CHAR, root, MPI_COMM_WORLD),
              "MPI_Bcast");
    }
    return result;
}

void Communicator::barrier() const
{
    if (parallel())
    {
        check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
    }
}

void Communicator::abort(int exitCode) const
{
    if (sessionOpen)
    {
        MPI_Abort(MPI_COMM_WORLD, exitCode);
    }
    std::_Exit(exitCode); // MPI_Abort does not return; without a session there is no one else
}

} // namespace sph
