#pragma once
// The particles of a distributed run: those a rank owns and, around them, its ghosts (copies of
// other ranks' particles within a width of its own; issue 14).
//
// The local particles, owned and ghosts together, are kept in increasing global id. That is
// what makes a distributed run bit-identical to the serial one: a neighbour list lists the
// neighbours in increasing local index (particles/NeighbourList.hpp), which is then increasing
// global id, the serial run's order, so every per-particle sum adds the same terms in the same
// order. Bodies also stay contiguous, as in the serial run, since global ids number the bodies
// one after another.
//
// What travels is the registry's stored fields (particles/ParticleFields.hpp), so a quantity
// declared once also migrates and is ghosted without further code: a migrating particle takes
// every stored field with it; a ghost is created with every stored field and refreshed with the
// fields the caller names (the ones that changed since); a ragged field (gradF's per-sample
// history) travels with its particle and reaches a ghost when it is created. Derived (display) fields are computed
// where they are written and never travel. Values travel as doubles: integers (up to 2^53) and
// doubles arrive with the same bits.
//
//   exchange.migrate(fields, globalId, rcbOwners<D>(comm, x, ids)); // owned only, sorted
//   exchange.addGhosts(fields, x, globalId, width);                 // + ghosts, sorted
//   ... owners change x, F ...
//   exchange.updateGhosts(fields, {"position", "F"});
//   exchange.removeGhosts(fields);                                   // before the next migrate
//
// The ghosts of a rank are every particle of another rank within `width` of the box around the
// rank's owned particles: a superset of the particles within `width` of an owned one, which is
// harmless (a neighbour search drops the farther ones) and needs only the ranks' boxes.

#include "parallel/Communicator.hpp"
#include "particles/ParticleFields.hpp"
#include "particles/Types.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sph
{

template <int D>
class ParticleExchange
{
public:
    explicit ParticleExchange(Communicator comm) : comm_(comm) {}

    // Sends local particle a, with all its stored fields, to rank destination[a]; after, the
    // local particles are the ones this rank owns, in increasing global id. There must be no
    // ghosts (removeGhosts first). Collective.
    void migrate(ParticleFields<D>& fields, const std::vector<int>& globalId,
                 const std::vector<int>& destination);

    // Adds the ghosts within `width` of this rank's owned particles, merged into the owned ones
    // in increasing global id (the owned particles' local indices change). `x` and `globalId`
    // are the registry's positions and ids. Collective.
    void addGhosts(ParticleFields<D>& fields, const std::vector<Vec<D>>& x,
                   const std::vector<int>& globalId, double width);

    // Several reaches: a particle is a ghost of a rank when it is within any reach's width of
    // that rank's owned particles, in that reach's positions (e.g. two search radii in the
    // reference configuration, and the contact range in the current one).
    struct GhostReach
    {
        const std::vector<Vec<D>>* x; // per local particle (owned: the ghosts are removed first)
        double width;
    };
    void addGhosts(ParticleFields<D>& fields, const std::vector<GhostReach>& reaches,
                   const std::vector<int>& globalId);

    // Copies the owners' values of the named stored fields onto the ghosts. Collective.
    void updateGhosts(ParticleFields<D>& fields, const std::vector<std::string>& names);

    // Copies the owners' values onto the ghosts for a per-local-particle array that is not a
    // stored field (a quantity computed on the owned particles and read at their ghosts, e.g.
    // the current volumes of contact). Collective.
    void updateGhostValues(std::vector<double>& values);

    // Drops the ghosts: the local particles are the owned ones again, in the same order.
    void removeGhosts(ParticleFields<D>& fields);

    // Keeps the local particles with keep[a] != 0, in the same order, as this rank's owned ones
    // (e.g. a share of a set every rank read whole, before the first migrate). No ghosts.
    void keepOnly(ParticleFields<D>& fields, const std::vector<std::uint8_t>& keep);

    // Per local particle: 1 owned, 0 ghost (all ones without ghosts).
    std::vector<std::uint8_t> ownedMask(std::size_t localCount) const
    {
        return owned_.empty() ? std::vector<std::uint8_t>(localCount, 1) : owned_;
    }

    bool owned(std::size_t a) const { return owned_.empty() || owned_[a] != 0; }
    std::size_t ownedCount() const { return ownedCount_; }
    std::size_t ghostCount() const { return ghostCount_; }
    // The values this rank sent in the last migrate, addGhosts or updateGhosts, in bytes, and in
    // all of them since this object was made.
    std::size_t bytesSent() const { return bytesSent_; }
    std::size_t totalBytesSent() const { return totalBytesSent_; }

private:
    // Per particle: its global id, every stored field, then each ragged field's entry count
    // and entries.
    using Rows = std::vector<double>;

    // The numbers of a row before its ragged fields.
    static std::size_t rowWidth(const ParticleFields<D>& fields);
    static std::vector<std::size_t> rowStarts(const ParticleFields<D>& fields, const Rows& rows);
    static void appendRow(const ParticleFields<D>& fields, std::size_t a, double globalId,
                          Rows& rows);
    // Replaces the local particles by these rows, in increasing global id; fills `origin` with
    // each new local particle's row index.
    void replaceBy(ParticleFields<D>& fields, const Rows& rows, std::vector<std::size_t>& origin);
    void countSent(const std::vector<Rows>& toEach);
    std::vector<std::size_t> receiveCounts(std::size_t perGhost) const;

    Communicator comm_;
    std::vector<std::uint8_t> owned_;                  // per local particle (empty: all owned)
    std::vector<std::vector<std::size_t>> sendTo_;     // per rank: owned local indices it ghosts
    std::vector<std::vector<std::size_t>> receiveAt_;  // per rank: local indices of its ghosts
    std::size_t ownedCount_ = 0;
    std::size_t ghostCount_ = 0;
    std::size_t bytesSent_ = 0;
    std::size_t totalBytesSent_ = 0;
};

} // namespace sph
