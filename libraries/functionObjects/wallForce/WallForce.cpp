// `wallForce`: what each rigid wall of constant/walls does to the solid (walls/WallSet.hpp).
// Columns, per wall W:
//   W_Fx W_Fy (W_Fz)  the force the wall exerts on the particles at x^n, Σ_a (F_n + F_t)
//                     [N; in 2D per unit thickness, N/m]; the load the solid puts on the wall
//                     (a footing's bearing load, the weight a floor carries) is its opposite
//   W_work            its work on the solid since t = 0 [J; 2D J/m]: moving and removing the
//                     wall, and friction (the energy audit's, so it is the `wallWork` of the
//                     `energy` table wall by wall)
// Results (summary.json): W_peakNormalForce (the largest |Σ_a F_n| seen at any level, not only
// the written rows: a plane's Σ_a |F_n|; for a box the normal part of its load, the contacts on
// opposite faces cancelling as they do on the body) and W_work at the end.
// Keys: writeInterval (see FunctionObject.hpp).
#include "core/InputError.hpp"
#include "functionObjects/FunctionObjectModel.hpp"

#include <algorithm>

namespace sph
{

template <int D>
class WallForce : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "Per rigid wall (constant/walls): the force it exerts on the solid and its "
               "cumulative work; the peak normal force in summary.json.";
    }
    static Schema schema() { return FunctionObjectModel<D>::commonSchema(); }

    WallForce(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args)
    {
        if (!args.wallNames || args.wallNames->empty())
        {
            throw InputError(params.source().location(),
                             "wallForce: the case has no walls to report on",
                             {"Declare them in constant/walls: floor { type plane; point (0 0); "
                              "normal (0 1); }"});
        }
        names_ = *args.wallNames;
        peak_.assign(names_.size(), 0.0);
        work_.assign(names_.size(), 0.0);
        static const char* axes[3] = {"x", "y", "z"};
        std::vector<std::string> columns;
        for (const auto& wall : names_)
        {
            for (int d = 0; d < D; ++d)
            {
                columns.push_back(wall + "_F" + axes[d]);
            }
            columns.push_back(wall + "_work");
        }
        this->setColumns(columns);
    }

    // The loads are the walls' own, summed over the ranks (walls/WallSet.hpp).
    bool distributable() const override { return true; }

    void execute(const StepState<D>& state) override
    {
        const WallLoads<D>& loads = *state.walls;
        for (std::size_t w = 0; w < names_.size(); ++w)
        {
            peak_[w] = std::max(peak_[w], loads.normalForce[w].norm());
            work_[w] = loads.work[w];
        }
        if (!this->rowDue(state.time, state.deltaT))
        {
            return;
        }
        std::vector<double> row;
        for (std::size_t w = 0; w < names_.size(); ++w)
        {
            for (int d = 0; d < D; ++d)
            {
                row.push_back(loads.force[w][d]);
            }
            row.push_back(loads.work[w]);
        }
        this->writeRow(state.time, state.deltaT, row);
    }

    std::map<std::string, double> results() const override
    {
        std::map<std::string, double> results;
        for (std::size_t w = 0; w < names_.size(); ++w)
        {
            results[names_[w] + "_peakNormalForce"] = peak_[w];
            results[names_[w] + "_work"] = work_[w];
        }
        return results;
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        FunctionObjectModel<D>::saveState(state);
        for (std::size_t w = 0; w < names_.size(); ++w)
        {
            state["peakNormalForce:" + names_[w]] = peak_[w];
        }
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        FunctionObjectModel<D>::restoreState(state);
        for (std::size_t w = 0; w < names_.size(); ++w)
        {
            peak_[w] = state.at("peakNormalForce:" + names_[w]);
        }
    }

private:
    std::vector<std::string> names_;
    std::vector<double> peak_; // by wall: the largest |Σ F_n| so far
    std::vector<double> work_; // by wall: the work at the last level seen
};

SPH_REGISTER_DIM_MODEL(FunctionObject, WallForce, "wallForce");

} // namespace sph
