#pragma once
// The case's rigid walls (constant/walls) and their contact law, one for every wall type.
//
// Contact: particle a is a sphere of radius r0 = s/2 (s the initial particle spacing). With its
// signed distance d_a from the wall and the wall's outward normal n̂ there (Wall::side; a plane's
// d_a = (x_a - p(t))·n̂), the penetration
//   δ_a = r0 - d_a > 0
// stores the potential φ_a = ½ k_a δ_a² and gives the normal force F_n = k_a δ_a n̂, with
//   k_a = M_b V0_a / s²,   M_b = ρ0 c0² of the particle's body (c0 = c(F = I)):
// the wall is as stiff as the material, not a tuning parameter. A particle against the wall
// is then an oscillator of ω = √(k_a/m_a) = c0/s, and with Δt = α h / c_max (α the Courant
// number, h = hOverDx s, c_max >= c0 at F = I)
//   ω Δt <= α hOverDx            (0.45 for α = 0.3, hOverDx = 1.5),
// well below the leapfrog's limit of 2; the solver refuses walls when α hOverDx >= 1, which
// leaves room for the particle's own internal stiffness.
// The bound holds for every wall shape whose signed distance d has |∇d| = 1 with n̂ = ∇d and is
// convex on the solid's side (a plane; a box, walls/box): the Hessian of φ_a is
//   k_a n̂ n̂ᵀ - k_a δ_a ∇²d,
// k_a along n̂ and, off an edge or a corner of a box (d the distance to a line or a point,
// ∇²d = (I - n̂ n̂ᵀ)/d), -k_a δ_a/d <= 0 across it: a particle slides off a corner (a physical
// instability, as a ball on a peak), which raises no frequency above c0/s.
//
// Friction (μ > 0): a tangential force opposing the sliding relative to the wall,
//   v_t = tangential part of (v^{n-1/2} + Δt_n a - V_wall),
//   F_t = -min(μ |F_n|, m_a |v_t| / Δt_n) v_t / |v_t|,
// where v^{n-1/2} + Δt_n a is the velocity the leapfrog's kick would give without friction
// (a = T/m + g and the walls before this one): friction can bring the sliding to rest within
// the step but not reverse it, and it holds a particle at rest exactly when μ |F_n| suffices
// (static friction). The kick is ½(Δt_{n-1} + Δt_n), not Δt_n; the two differ only when Δt is
// recomputed and then by the relative change of the wave speed, a slip of that order.
//
// The forces act in the `accelerate` phase, a^n = T/m + g + Σ_walls F/m, at x^n and t^n, so
// the leapfrog integrates the (position-dependent, conservative) normal force symplectically.
// Fixed particles are skipped; a wall past its removeAt time costs nothing.
//
// Energy (kept by the solver's EnergyAudit): Φ = Σ φ_a is stored energy; the wall's work W
// (moving or removing the wall, and friction) is done on the solid, so that
//   kinetic + strain + Φ - W_external - W_contact - W = the value at t = 0.
// Over a step x^n -> x^{n+1}, t^n -> t^{n+1}, per wall
//   W_motion   = ½ [Φ(x^{n+1}, t^{n+1}) - Φ(x^{n+1}, t^n) + Φ(x^n, t^{n+1}) - Φ(x^n, t^n)]
//                (the potential the wall's own motion adds; exact to second order, and a wall
//                removed within the step takes its stored energy with it: Φ(·, t^{n+1}) = 0),
//   W_friction = ½ (F_t^n + F_t^{n+1})·(x^{n+1} - x^n)
//                (the trapezoid rule the leapfrog's kinetic energy follows; the half with
//                F_t^{n+1} is added at the next level, once that force is known).

#include "core/InputError.hpp"
#include "core/Suggest.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "materials/Material.hpp"
#include "particles/ParticleRanks.hpp"
#include "particles/ParticleSet.hpp"
#include "walls/Wall.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace sph
{

template <int D>
class WallSet
{
public:
    // `walls` is constant/walls (null when the case has none).
    WallSet(const Dictionary* walls, const std::vector<std::string>& bodyNames,
            const std::vector<const Material<D>*>& materials, double spacing)
        : radius_(0.5 * spacing)
    {
        for (const Material<D>* material : materials)
        {
            const double c0 = material->waveSpeed(Mat<D>::Identity());
            stiffness_.push_back(material->density() * c0 * c0 / (spacing * spacing));
        }
        if (!walls)
        {
            return;
        }
        for (const Entry& entry : walls->entries())
        {
            if (!entry.isDict())
            {
                throw InputError(entry.keyLocation(),
                                 "'" + entry.key() + "' in constant/walls must be a dictionary { "
                                                     "type ...; ... }",
                                 {"Valid wall types: " + joinSorted(Registry<Wall<D>>::names())});
            }
            walls_.push_back(selectModel<Wall<D>>(entry.dict(), {bodyNames}, D,
                                                  Selection::withBodies(bodyNames)));
            loads_.names.push_back(entry.key());
        }
        loads_.force.assign(walls_.size(), Vec<D>::Zero());
        loads_.normalForce.assign(walls_.size(), Vec<D>::Zero());
        loads_.work.assign(walls_.size(), 0.0);
        contacts_.resize(walls_.size());
        work_.assign(walls_.size(), 0.0);
    }

    bool empty() const { return walls_.empty(); }

    // A distributed run (particles/ParticleRanks.hpp): each rank applies the walls to the
    // particles it owns, and the loads, the potential and the work are summed over the ranks
    // (they only report: the energy audit and wallForce).
    void setRanks(const ParticleRanks* ranks) { ranks_ = ranks; }
    const std::vector<std::string>& names() const { return loads_.names; }

    // Run-header lines: each wall's summary.
    std::vector<std::string> describe() const
    {
        std::vector<std::string> lines;
        for (std::size_t w = 0; w < walls_.size(); ++w)
        {
            lines.push_back(loads_.names[w] + ": " + walls_[w]->summary());
        }
        return lines;
    }

    // Level n: adds each present wall's force to a (= T/m + g on entry) at x^n, t^n; v is the
    // integrator's v^{n-1/2} and dt = Δt_n (see the header for friction). Also the potential
    // Φ^n and the loads of the level.
    void applyForces(const ParticleSet<D>& p, const std::vector<Vec<D>>& v, double t, double dt,
                     std::vector<Vec<D>>& a)
    {
        potential_ = 0.0;
        for (std::size_t w = 0; w < walls_.size(); ++w)
        {
            const Wall<D>& wall = *walls_[w];
            Vec<D> total = Vec<D>::Zero();
            Vec<D> normalTotal = Vec<D>::Zero();
            contacts_[w].clear();
            forEachParticle(p, w, t, [&](std::size_t i) {
                const auto side = wall.side(p.x[i], t);
                const double depth = radius_ - side.distance;
                if (!(depth > 0.0))
                {
                    return;
                }
                const double k = stiffness(p, i);
                const double normal = k * depth;
                potential_ += 0.5 * k * depth * depth;
                const Vec<D> normalForce = normal * side.normal;
                Vec<D> force = normalForce;
                if (wall.friction() > 0.0)
                {
                    const Vec<D> friction = frictionForce(wall, side.normal, normal, p.m[i],
                                                          v[i] + dt * a[i], dt);
                    contacts_[w].push_back({i, friction});
                    force += friction;
                }
                a[i] += force / p.m[i];
                total += force;
                normalTotal += normalForce;
            });
            loads_.force[w] = total;
            loads_.normalForce[w] = normalTotal;
        }
        if (ranks_)
        {
            std::vector<double> sums;
            for (std::size_t w = 0; w < walls_.size(); ++w)
            {
                sums.insert(sums.end(), loads_.force[w].data(), loads_.force[w].data() + D);
                sums.insert(sums.end(), loads_.normalForce[w].data(),
                            loads_.normalForce[w].data() + D);
            }
            sums.push_back(potential_);
            ranks_->sum(sums);
            for (std::size_t w = 0; w < walls_.size(); ++w)
            {
                std::copy_n(&sums[w * 2 * D], D, loads_.force[w].data());
                std::copy_n(&sums[w * 2 * D + D], D, loads_.normalForce[w].data());
            }
            potential_ = sums.back();
        }
    }

    // Φ^n = Σ φ_a of the last applyForces.
    double potential() const { return potential_; }
    // The loads of the last applyForces (their `work` is the caller's to fill).
    const WallLoads<D>& loads() const { return loads_; }

    // The wall work over the drift x^n -> x^{n+1} from t^n over dt, per wall: the motion (and
    // removal) work and the first half of the friction work (see the header).
    const std::vector<double>& driftWork(const ParticleSet<D>& p, const std::vector<Vec<D>>& xOld,
                                         double t, double dt)
    {
        const double next = t + dt; // as the solver advances its time
        for (std::size_t w = 0; w < walls_.size(); ++w)
        {
            const Wall<D>& wall = *walls_[w];
            double work = 0.5 * frictionWork(w, p.x, xOld);
            if (wall.presentAt(t) && (wall.moves() || !wall.presentAt(next)))
            {
                double motion = 0.0;
                forEachParticle(p, w, t, [&](std::size_t i) {
                    motion += potential(wall, p, i, p.x[i], next) - potential(wall, p, i, p.x[i], t) +
                              potential(wall, p, i, xOld[i], next) - potential(wall, p, i, xOld[i], t);
                });
                work += 0.5 * motion;
            }
            work_[w] = work;
        }
        if (ranks_)
        {
            ranks_->sum(work_);
        }
        frictionPending_ = true;
        return work_;
    }

    // At level n+1 after applyForces: the second half of the friction work of the last drift
    // (zero at the first level of a run: a restart's output already holds it).
    const std::vector<double>& completeFrictionWork(const std::vector<Vec<D>>& x,
                                                    const std::vector<Vec<D>>& xOld)
    {
        for (std::size_t w = 0; w < walls_.size(); ++w)
        {
            work_[w] = frictionPending_ ? 0.5 * frictionWork(w, x, xOld) : 0.0;
        }
        if (ranks_)
        {
            ranks_->sum(work_);
        }
        frictionPending_ = false;
        return work_;
    }

private:
    struct FrictionContact
    {
        std::size_t particle;
        Vec<D> force;
    };

    // Calls f(i) for the free particles of the bodies wall w acts on, if it is present at t.
    template <class F>
    void forEachParticle(const ParticleSet<D>& p, std::size_t w, double t, F&& f) const
    {
        if (!walls_[w]->presentAt(t))
        {
            return;
        }
        for (std::size_t b = 0; b < p.bodies.size(); ++b)
        {
            if (!walls_[w]->actsOn(b))
            {
                continue;
            }
            for (std::size_t i = p.bodies[b].begin; i < p.bodies[b].end; ++i)
            {
                if (!p.fixed[i] && (!ranks_ || ranks_->counts(i)))
                {
                    f(i);
                }
            }
        }
    }

    double stiffness(const ParticleSet<D>& p, std::size_t i) const
    {
        return stiffness_[static_cast<std::size_t>(p.body[i])] * p.V0[i];
    }

    // φ_a of particle i at position x and time t (0 once the wall is removed).
    double potential(const Wall<D>& wall, const ParticleSet<D>& p, std::size_t i, const Vec<D>& x,
                     double t) const
    {
        if (!wall.presentAt(t))
        {
            return 0.0;
        }
        const double depth = radius_ - wall.side(x, t).distance;
        return depth > 0.0 ? 0.5 * stiffness(p, i) * depth * depth : 0.0;
    }

    // F_t opposing the tangential velocity relative to the wall that the kick would give.
    static Vec<D> frictionForce(const Wall<D>& wall, const Vec<D>& normal, double normalForce,
                                double mass, const Vec<D>& predicted, double dt)
    {
        const Vec<D> relative = predicted - wall.velocity();
        const Vec<D> tangential = relative - relative.dot(normal) * normal;
        const double speed = tangential.norm();
        if (!(speed > 0.0))
        {
            return Vec<D>::Zero();
        }
        const double coulomb = wall.friction() * normalForce;
        const double magnitude = dt > 0.0 ? std::min(coulomb, mass * speed / dt) : coulomb;
        return (-magnitude / speed) * tangential;
    }

    // Σ F_t·(x - xOld) over wall w's friction contacts of the last applyForces.
    double frictionWork(std::size_t w, const std::vector<Vec<D>>& x,
                        const std::vector<Vec<D>>& xOld) const
    {
        double work = 0.0;
        for (const FrictionContact& contact : contacts_[w])
        {
            work += contact.force.dot(x[contact.particle] - xOld[contact.particle]);
        }
        return work;
    }

    double radius_;                      // r0 = s/2
    const ParticleRanks* ranks_ = nullptr; // a distributed run's (null: serial)
    std::vector<double> stiffness_;      // by body: M_b / s², so that k_a = stiffness V0_a
    std::vector<std::unique_ptr<Wall<D>>> walls_;
    WallLoads<D> loads_;
    std::vector<std::vector<FrictionContact>> contacts_; // by wall, of the last applyForces
    std::vector<double> work_;           // by wall, the increment last returned
    double potential_ = 0.0;
    bool frictionPending_ = false;       // a drift's friction work awaits its second half
};

} // namespace sph
