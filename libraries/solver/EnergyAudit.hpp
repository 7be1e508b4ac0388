#pragma once
// The energy audit of a run (spec §10, §12): the work of external (body) forces, of the
// contact kicks and of each rigid wall accumulated over the steps, and the balance at a level,
//
//   total = Σ ½ m |v^n|^2 + Π^n + Φ^n + D + K_damped - W_external - W_contact - W_walls - W_visc,
//   drift = (total - total_0)/|total_0|,
//
// with W_visc the work of the artificial viscosity (<= 0: the energy it dissipates is
// -W_visc), Φ the walls' stored potential and W_walls their work (walls/WallSet.hpp), and D the
// energy dissipated by the materials' committed plastic flow (docs/theory/plasticity.md
// (P5.3)), K_damped the kinetic energy that kinetic damping removed (docs/theory/
// geotechnics.md §E2); Π^n of a material with history is its incremental energy, which holds the current
// step's dissipation until the commit moves it into D.
//
// One owner: the run log's drift and the `energy` function object's table both read it.
// Sums are serial, in particle order, so they do not depend on the number of threads.

#include "core/RunScalars.hpp"
#include "functionObjects/FunctionObject.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace sph
{

template <int D>
class EnergyAudit
{
public:
    // A distributed run: only the owned particles count (a ghost is counted by its owner), and
    // each sum is completed over the ranks by `total` (in rank order: the same bits on every
    // rank). The mask is read at each sum (the run changes it as particles migrate).
    void countOwned(const std::vector<std::uint8_t>* owned, std::function<double(double)> total)
    {
        owned_ = owned;
        total_ = std::move(total);
    }
    void declareState(RunScalars& scalars, const std::vector<std::string>& wallNames = {})
    {
        scalars.bind("externalWork", external_);
        scalars.bind("contactWork", contact_.work);
        scalars.bind("initialEnergy", initial_);
        scalars.bind("haveInitialEnergy", haveInitial_);
        wallWork_.assign(wallNames.size(), 0.0); // not resized again: the scalars point into it
        for (std::size_t w = 0; w < wallNames.size(); ++w)
        {
            scalars.bind("wallWork:" + wallNames[w], wallWork_[w]);
        }
    }

    // Only when a material keeps a plastic history (its restart scalar and column).
    void declareDissipation(RunScalars& scalars) { scalars.bind("dissipatedEnergy", dissipated_); }

    // Only with an artificial viscosity other than `none` (its restart scalar and column).
    void declareViscousWork(RunScalars& scalars) { scalars.bind("viscousWork", viscous_); }

    // Only with kinetic damping (its restart scalar and column).
    void declareDamping(RunScalars& scalars) { scalars.bind("dampedEnergy", damped_); }

    // Σ ½ m |v|^2 over the counted particles, completed over the ranks.
    double kineticEnergy(const std::vector<double>& m, const std::vector<Vec<D>>& velocity) const
    {
        double kinetic = 0.0;
        for (std::size_t a = 0; a < m.size(); ++a)
        {
            kinetic += counts(a) ? 0.5 * m[a] * velocity[a].squaredNorm() : 0.0;
        }
        return total(kinetic);
    }

    // The viscous forces m a_visc do the work ½(F^n + F^{n+1})·(x^{n+1} - x^n) over a step,
    // the trapezoid rule the leapfrog's kinetic energy follows (as for wall friction): the half
    // with F^n at the drift, the half with F^{n+1} at the next level, once it is known (not at
    // the first level of a run: a restart's output already holds it).
    void addViscousDrift(const std::vector<double>& m, const std::vector<Vec<D>>& aVisc,
                         const std::vector<Vec<D>>& xNew, const std::vector<Vec<D>>& xOld)
    {
        viscous_ += halfWork(m, aVisc, xNew, xOld);
        viscousPending_ = true;
    }
    void completeViscousWork(const std::vector<double>& m, const std::vector<Vec<D>>& aVisc,
                             const std::vector<Vec<D>>& x, const std::vector<Vec<D>>& xOld)
    {
        if (viscousPending_)
        {
            viscous_ += halfWork(m, aVisc, x, xOld);
        }
        viscousPending_ = false;
    }

    // Work done by each wall on the solid over a step, or part of one (walls/WallSet.hpp).
    void addWallWork(const std::vector<double>& work)
    {
        for (std::size_t w = 0; w < wallWork_.size(); ++w)
        {
            wallWork_[w] += work[w];
        }
    }
    const std::vector<double>& wallWork() const { return wallWork_; }

    // Work of a constant body force g over the drift x^n -> x^{n+1}: Σ m g·(x^{n+1} - x^n).
    void addGravityWork(const std::vector<double>& m, const Vec<D>& g,
                        const std::vector<Vec<D>>& xNew, const std::vector<Vec<D>>& xOld)
    {
        double work = 0.0;
        for (std::size_t a = 0; a < m.size(); ++a)
        {
            work += counts(a) ? m[a] * g.dot(xNew[a] - xOld[a]) : 0.0;
        }
        external_ += total(work);
    }

    // Only when a function object tabulates the moves' energy (their restart scalars).
    void declareMoveEnergy(RunScalars& scalars)
    {
        scalars.bind("moveEnergySum", moveSum_);
        scalars.bind("moveEnergyGain", moveGain_);
        scalars.bind("moveEnergyLargest", moveLargest_);
    }
    // What one move of the reference configuration changed Π by, at fixed positions (§G6).
    void addMoveChange(double change)
    {
        moveSum_ += change;
        moveGain_ += std::max(change, 0.0);
        moveLargest_ = std::max(moveLargest_, change);
    }

    // Energy dissipated by a commit of the materials' history.
    void addDissipation(double energy) { dissipated_ += energy; }

    // A contact kick Δv applied to v^{n+1/2} over a step dt; its work W_contact is completed
    // at the next level (kick(), completeKick()).
    void addContactKick(const std::vector<double>& m, const std::vector<Vec<D>>& deltaV,
                        const std::vector<Vec<D>>& vAfter, double dt)
    {
        kick(contact_, m, deltaV, vAfter, dt);
    }
    void completeContactWork(const std::vector<double>& m, const std::vector<Vec<D>>& deltaV,
                             const std::vector<Vec<D>>& acceleration)
    {
        completeKick(contact_, m, deltaV, acceleration);
    }

    // A reset of kinetic damping after a step of `dt` (geotechnics.md (E2.3)): the particles
    // are at rest at the level x^{n+1}, where the undamped step would have had
    // v^{n+1} = v^{n+1/2} + ½Δt a^{n+1}; the kinetic energy that removes, Σ ½ m |v^{n+1}|², is
    // booked at that level, once a^{n+1} is known.
    void addDampingReset(double dt)
    {
        dampingPending_ = true;
        dampingDeltaT_ = dt;
    }
    void completeDamping(const std::vector<double>& m, const std::vector<Vec<D>>& removed,
                         const std::vector<Vec<D>>& acceleration)
    {
        if (!dampingPending_)
        {
            return;
        }
        double energy = 0.0;
        for (std::size_t a = 0; a < m.size(); ++a)
        {
            energy += counts(a) ? 0.5 * m[a] *
                                      (removed[a] + 0.5 * dampingDeltaT_ * acceleration[a])
                                          .squaredNorm()
                                : 0.0;
        }
        damped_ += total(energy);
        dampingPending_ = false;
    }

    // The balance at a level with velocities v^n, strain energy Π^n and wall potential Φ^n;
    // the first balance of a run is the reference of the drift.
    EnergyBalance balance(const std::vector<double>& m, const std::vector<Vec<D>>& velocity,
                          double strainEnergy, double wallPotential = 0.0)
    {
        EnergyBalance e;
        e.kinetic = kineticEnergy(m, velocity);
        e.strain = strainEnergy;
        e.external = external_;
        e.contact = contact_.work;
        e.wallPotential = wallPotential;
        for (const double work : wallWork_)
        {
            e.wallWork += work;
        }
        e.dissipated = dissipated_;
        e.viscousWork = viscous_;
        e.damped = damped_;
        e.moveSum = moveSum_;
        e.moveGain = moveGain_;
        e.moveLargest = moveLargest_;
        e.total = e.kinetic + e.strain + e.wallPotential + e.dissipated + e.damped - e.external -
                  e.contact - e.wallWork - e.viscousWork;
        if (!haveInitial_)
        {
            initial_ = e.total;
            haveInitial_ = true;
        }
        const double scale = std::abs(initial_) > 0.0 ? std::abs(initial_) : 1.0;
        e.drift = (e.total - initial_) / scale;
        return e;
    }

private:
    // The work of a velocity change Δv applied to v^{n+1/2} over a step dt (spec §12):
    //   ΔW = Σ m Δv·(v^{n+1/2} + ½Δv + ½Δt a^{n+1});
    // the part known at the kick (v_after = v_before + Δv) is added then, the part with
    // a^{n+1} at the next level, once it is known.
    struct Kick
    {
        double work = 0.0;
        bool pending = false;
        double deltaT = 0.0;
    };
    void kick(Kick& k, const std::vector<double>& m, const std::vector<Vec<D>>& deltaV,
              const std::vector<Vec<D>>& vAfter, double dt)
    {
        double work = 0.0;
        for (std::size_t a = 0; a < m.size(); ++a)
        {
            work += counts(a) ? m[a] * deltaV[a].dot(vAfter[a] - 0.5 * deltaV[a]) : 0.0;
        }
        k.work += total(work);
        k.pending = true;
        k.deltaT = dt;
    }
    void completeKick(Kick& k, const std::vector<double>& m, const std::vector<Vec<D>>& deltaV,
                      const std::vector<Vec<D>>& acceleration)
    {
        if (!k.pending)
        {
            return;
        }
        double work = 0.0;
        for (std::size_t a = 0; a < m.size(); ++a)
        {
            work += counts(a) ? m[a] * deltaV[a].dot(acceleration[a]) : 0.0;
        }
        k.work += 0.5 * k.deltaT * total(work);
        k.pending = false;
    }

    bool counts(std::size_t a) const { return !owned_ || (*owned_)[a] != 0; }
    double total(double local) const { return total_ ? total_(local) : local; }

    // ½ Σ m a·(x - xOld)
    double halfWork(const std::vector<double>& m, const std::vector<Vec<D>>& a,
                    const std::vector<Vec<D>>& x, const std::vector<Vec<D>>& xOld) const
    {
        double work = 0.0;
        for (std::size_t i = 0; i < m.size(); ++i)
        {
            work += counts(i) ? m[i] * a[i].dot(x[i] - xOld[i]) : 0.0;
        }
        return 0.5 * total(work);
    }

    const std::vector<std::uint8_t>* owned_ = nullptr;
    std::function<double(double)> total_;

    double external_ = 0.0;
    double viscous_ = 0.0;         // W_visc
    bool viscousPending_ = false;  // the half of the last drift's viscous work with F^{n+1}
    Kick contact_;                 // W_contact
    double damped_ = 0.0;          // K_damped
    bool dampingPending_ = false;  // a reset whose energy is booked at the next level
    double dampingDeltaT_ = 0.0;
    double dissipated_ = 0.0;
    double moveSum_ = 0.0;     // Σ ΔΠ over the reference moves
    double moveGain_ = 0.0;    // Σ max(ΔΠ, 0)
    double moveLargest_ = 0.0; // max ΔΠ of one move (0 while none rose)
    std::vector<double> wallWork_; // by wall
    double initial_ = 0.0;
    bool haveInitial_ = false;
};

} // namespace sph
