// `energy`: the energy balance with the scheme's own discrete energy Π (spec §10).
// Columns: kinetic strain external contact dissipated total drift, where
//   kinetic  = Σ ½ m |v^n|^2 (v^n = ½(v^{n-1/2} + v^{n+1/2})),
//   strain   = Π(x^n) of the selected scheme (with plastic materials: the incremental energy,
//              docs/theory/plasticity.md (P4.2)),
//   external = work done by external (body) forces since t = 0,
//   contact  = work done by contact forces since t = 0,
//   wallPotential, wallWork (only in a case with constant/walls) = Σ ½ k δ² of the walls and
//              their work since t = 0: moving, removing, friction (walls/WallSet.hpp),
//   viscousWork (only with an artificialViscosity other than none) = work of the artificial
//              viscosity since t = 0, <= 0 (the energy it dissipated is -viscousWork),
//   dissipated (only when a material keeps a plastic history) = energy dissipated by plastic
//              flow since t = 0,
//   damped (only with timeIntegration's kineticDamping) = kinetic energy its resets of the
//              velocities removed since t = 0 (docs/theory/geotechnics.md §E2),
//   total    = kinetic + strain + wallPotential + dissipated + damped - external - contact
//              - wallWork - viscousWork (conserved by an exact integrator),
//   drift    = (total - total(0)) / |total(0)|,
//   moveEnergySum, moveEnergyGain, moveEnergyLargest (only with referenceMoves yes) = what the
//              moves of the reference configuration changed Π by since t = 0, at fixed
//              positions: their sum, the sum of the positive changes and the largest one
//              (docs/theory/gradF-plastic.md §G6; moves that make no energy keep Gain at
//              round-off),
//   momentum_x .. (Σ m v) and, in 2D/3D, angularMomentum (Σ m x × v; _x _y _z in 3D):
//   conserved by the internal forces and the contact kick, changed by fixed particles and
//   external forces (spec §10).
// Keys: writeInterval (see FunctionObject.hpp),
//   referenceMoves | Π before and after every reference move (one energy evaluation per
//                    move: the reference moves every step in updated Lagrangian) | no
#include "core/Format.hpp"
#include "functionObjects/FunctionObjectModel.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace sph
{

template <int D> class Energy : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "Energy balance: kinetic, strain (the scheme's own energy), external and contact "
               "work, plastic dissipation, total and its relative drift.";
    }
    static Schema schema()
    {
        return FunctionObjectModel<D>::commonSchema().add(
            Key::boolean("referenceMoves",
                         "tabulate what each move of the reference configuration changes the "
                         "strain energy by (costs one energy evaluation per move)")
                .defaultValue("no"));
    }

    Energy(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args), withMoves_(params.boolean("referenceMoves"))
    {
        std::vector<std::string> columns{"kinetic", "strain", "external", "contact"};
        withWalls_ = args.wallNames && !args.wallNames->empty();
        if (withWalls_)
        {
            columns.insert(columns.end(), {"wallPotential", "wallWork"});
        }
        withViscosity_ = args.artificialViscosity;
        if (withViscosity_)
        {
            columns.push_back("viscousWork");
        }
        for (const Material<D>* material : args.materials ? *args.materials : noMaterials())
        {
            withDissipation_ = withDissipation_ || material->hasHistory();
        }
        if (withDissipation_)
        {
            columns.push_back("dissipated");
        }
        withDamping_ = args.kineticDamping;
        if (withDamping_)
        {
            columns.push_back("damped");
        }
        columns.insert(columns.end(), {"total", "drift"});
        if (withMoves_)
        {
            columns.insert(columns.end(), {"moveEnergySum", "moveEnergyGain", "moveEnergyLargest"});
        }
        static const char* axes[3] = {"x", "y", "z"};
        for (int d = 0; d < D; ++d)
        {
            columns.push_back(std::string("momentum_") + axes[d]);
        }
        if (D == 2)
        {
            columns.push_back("angularMomentum");
        }
        for (int d = 0; D == 3 && d < 3; ++d)
        {
            columns.push_back(std::string("angularMomentum_") + axes[d]);
        }
        this->setColumns(columns);
    }

    bool needsMoveEnergy() const override { return withMoves_; }

    bool needsEnergy(long, double time) const override
    {
        return this->rowDue(time, lastDeltaT_);
    }

    // The balance itself is the solver's energy audit (the one the run log prints); this
    // object tabulates it with the momenta and keeps the extremes.
    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        lastDeltaT_ = state.deltaT;
        if (!this->rowDue(state.time, state.deltaT) || !state.energy)
        {
            return;
        }
        const EnergyBalance& e = *state.energy;
        drift_ = e.drift;
        maxDrift_ = std::max(maxDrift_, std::abs(drift_));
        if (e.kinetic > 0.0)
        {
            maxStrainRatio_ = std::max(maxStrainRatio_, e.strain / e.kinetic);
        }
        std::vector<double> row{e.kinetic, e.strain, e.external, e.contact};
        if (withWalls_)
        {
            row.insert(row.end(), {e.wallPotential, e.wallWork});
        }
        if (withViscosity_)
        {
            row.push_back(e.viscousWork);
        }
        if (withDissipation_)
        {
            row.push_back(e.dissipated);
        }
        if (withDamping_)
        {
            row.push_back(e.damped);
        }
        row.insert(row.end(), {e.total, e.drift});
        if (withMoves_)
        {
            row.insert(row.end(), {e.moveSum, e.moveGain, e.moveLargest});
            moveGain_ = e.moveGain;
            moveLargest_ = e.moveLargest;
        }
        // The momenta over the owned particles, then over the ranks (round-off: a sum).
        const ParticleSet<D>& p = state.particles;
        const ParticleRanks& ranks = state.rankView();
        Vec<D> momentum = Vec<D>::Zero();
        Eigen::Vector3d angular = Eigen::Vector3d::Zero();
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            if (!ranks.counts(a))
            {
                continue;
            }
            const Vec<D> m = p.m[a] * state.velocity[a];
            momentum += m;
            angular += embed<D>(p.x[a]).cross(embed<D>(m));
        }
        std::vector<double> momenta(momentum.data(), momentum.data() + D);
        if (D == 2)
        {
            momenta.push_back(angular[2]);
        }
        for (int d = 0; D == 3 && d < 3; ++d)
        {
            momenta.push_back(angular[d]);
        }
        ranks.sum(momenta);
        row.insert(row.end(), momenta.begin(), momenta.end());
        this->writeRow(state.time, state.deltaT, row);
    }

    std::vector<std::string> report() const override
    {
        std::vector<std::string> lines{this->name() + ": total energy drift at the end " +
                                       formatScientific(drift_) + ", largest |drift| " +
                                       formatScientific(maxDrift_)};
        if (withMoves_)
        {
            lines.push_back(this->name() + ": reference moves raised the strain energy by " +
                            formatScientific(moveGain_) + " J in all, " +
                            formatScientific(moveLargest_) + " J at most in one move");
        }
        return lines;
    }
    std::map<std::string, double> results() const override
    {
        std::map<std::string, double> r{{"finalDrift", drift_},
                                        {"maxDrift", maxDrift_},
                                        {"maxStrainOverKinetic", maxStrainRatio_}};
        if (withMoves_)
        {
            r["moveEnergyGain"] = moveGain_;
            r["moveEnergyLargest"] = moveLargest_;
        }
        return r;
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        FunctionObjectModel<D>::saveState(state);
        state["maxDrift"] = maxDrift_;
        state["maxStrainRatio"] = maxStrainRatio_;
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        FunctionObjectModel<D>::restoreState(state);
        maxDrift_ = state.at("maxDrift");
        maxStrainRatio_ = state.at("maxStrainRatio");
    }

private:
    bool withWalls_ = false; // the case has constant/walls: their columns
    bool withViscosity_ = false; // an artificial viscosity is selected: its column
    bool withDissipation_ = false; // a material keeps a plastic history: its column
    bool withDamping_ = false;     // kinetic damping: its column
    bool withMoves_ = false;       // referenceMoves yes: the moves' columns
    double moveGain_ = 0.0;        // of the last row (the audit keeps the restart state)
    double moveLargest_ = 0.0;
    static const std::vector<const Material<D>*>& noMaterials()
    {
        static const std::vector<const Material<D>*> none;
        return none;
    }
    double lastDeltaT_ = 0.0;
    double drift_ = 0.0;
    double maxDrift_ = 0.0;
    double maxStrainRatio_ = 0.0; // largest strain / kinetic energy
};

SPH_REGISTER_DIM_MODEL(FunctionObject, Energy, "energy");

} // namespace sph
