// `extent`: per body, the largest and smallest displacement along one axis and the bounding
// box over time (the seed's Fig. 9 plots the largest y-displacement of each ring).
// Keys:
//   component | the displacement component: x, y or z   | y (x in 1D)
//   bodies    | which bodies ( ) = all                    | ()
// Columns per body B: B_maxDisplacement B_minDisplacement, then B_min_x B_max_x (B_min_y ...)
// of the current bounding box; summary.json: the peak displacement and when, and the last
// bounding box (B_final_min_x, B_final_max_x, ...) of the particle centres.
#include "functionObjects/FunctionObjectModel.hpp"

#include <limits>

namespace sph
{

template <int D>
class Extent : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "Per body: largest and smallest displacement along an axis, and the bounding box "
               "(seed Fig. 9).";
    }
    static Schema schema()
    {
        return FunctionObjectModel<D>::commonSchema()
            .add(Key::word("component", "displacement component").choices({"x", "y", "z"}).optional())
            .add(Key::bodyList("bodies", "which bodies; () = all").distinct().defaultValue("()"));
    }

    Extent(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args)
    {
        static const char* axes[3] = {"x", "y", "z"};
        const std::string component = params.has("component") ? params.word("component")
                                                               : (D == 1 ? "x" : "y");
        component_ = component == "x" ? 0 : component == "y" ? 1 : 2;
        if (component_ >= D)
        {
            params.fail("component", "extent: component '" + component + "' does not exist in " +
                                         std::to_string(D) + "D");
        }
        const auto& names = *args.bodyNames;
        bodies_ = params.bodyIndices("bodies");
        if (bodies_.empty())
        {
            for (std::size_t b = 0; b < names.size(); ++b)
            {
                bodies_.push_back(b);
            }
        }
        std::vector<std::string> columns;
        for (const std::size_t b : bodies_)
        {
            const std::string& name = names[b];
            columns.push_back(name + "_maxDisplacement");
            columns.push_back(name + "_minDisplacement");
            for (int d = 0; d < D; ++d)
            {
                columns.push_back(name + "_min_" + axes[d]);
                columns.push_back(name + "_max_" + axes[d]);
            }
            names_.push_back(name);
        }
        peaks_.assign(bodies_.size(), {std::numeric_limits<double>::lowest(), 0.0});
        lastLow_.assign(bodies_.size(), Eigen::Vector3d::Zero());
        lastHigh_.assign(bodies_.size(), Eigen::Vector3d::Zero());
        this->setColumns(columns);
    }

    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        const ParticleSet<D>& p = state.particles;
        const ParticleRanks& ranks = state.rankView();
        // Per body, the largest of: u, -u, -x_d, x_d over the particles this rank owns, then
        // over the ranks (a maximum: the serial values, bit for bit).
        const std::size_t perBody = 2 + 2 * D;
        std::vector<double> largest(bodies_.size() * perBody, std::numeric_limits<double>::lowest());
        for (std::size_t i = 0; i < bodies_.size(); ++i)
        {
            const BodyRange& range = p.bodies[bodies_[i]];
            double* body = &largest[i * perBody];
            for (std::size_t a = range.begin; a < range.end; ++a)
            {
                if (!ranks.counts(a))
                {
                    continue;
                }
                const double u = p.x[a][component_] - p.X[a][component_];
                body[0] = std::max(body[0], u);
                body[1] = std::max(body[1], -u);
                for (int d = 0; d < D; ++d)
                {
                    body[2 + 2 * d] = std::max(body[2 + 2 * d], -p.x[a][d]);
                    body[3 + 2 * d] = std::max(body[3 + 2 * d], p.x[a][d]);
                }
            }
        }
        ranks.maximum(largest);
        std::vector<double> row;
        for (std::size_t i = 0; i < bodies_.size(); ++i)
        {
            const double* body = &largest[i * perBody];
            if (body[0] > peaks_[i].first)
            {
                peaks_[i] = {body[0], state.time};
            }
            Vec<D> low;
            Vec<D> high;
            for (int d = 0; d < D; ++d)
            {
                low[d] = -body[2 + 2 * d];
                high[d] = body[3 + 2 * d];
            }
            lastLow_[i] = embed<D>(low);
            lastHigh_[i] = embed<D>(high);
            row.push_back(body[0]);
            row.push_back(-body[1]);
            for (int d = 0; d < D; ++d)
            {
                row.push_back(low[d]);
                row.push_back(high[d]);
            }
        }
        if (this->rowDue(state.time, state.deltaT))
        {
            this->writeRow(state.time, state.deltaT, row);
        }
    }

    std::vector<std::string> report() const override
    {
        std::vector<std::string> lines;
        for (std::size_t i = 0; i < names_.size(); ++i)
        {
            char line[256];
            std::snprintf(line, sizeof line, "%s: %s largest displacement %.4e m at t = %.4e s",
                          this->name().c_str(), names_[i].c_str(), peaks_[i].first,
                          peaks_[i].second);
            lines.push_back(line);
        }
        return lines;
    }
    std::map<std::string, double> results() const override
    {
        std::map<std::string, double> values;
        for (std::size_t i = 0; i < names_.size(); ++i)
        {
            values[names_[i] + "_peakDisplacement"] = peaks_[i].first;
            values[names_[i] + "_peakTime"] = peaks_[i].second;
            // The bounding box of the particle centres at the last level seen (a final shape).
            static const char* axes[3] = {"x", "y", "z"};
            for (int d = 0; d < D; ++d)
            {
                values[names_[i] + "_final_min_" + axes[d]] = lastLow_[i][d];
                values[names_[i] + "_final_max_" + axes[d]] = lastHigh_[i][d];
            }
        }
        return values;
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        FunctionObjectModel<D>::saveState(state);
        for (std::size_t i = 0; i < peaks_.size(); ++i)
        {
            state["peak" + std::to_string(i)] = peaks_[i].first;
            state["peakTime" + std::to_string(i)] = peaks_[i].second;
        }
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        FunctionObjectModel<D>::restoreState(state);
        for (std::size_t i = 0; i < peaks_.size(); ++i)
        {
            peaks_[i] = {state.at("peak" + std::to_string(i)), state.at("peakTime" + std::to_string(i))};
        }
    }

private:
    int component_ = 1;
    std::vector<std::size_t> bodies_;
    std::vector<std::string> names_;
    std::vector<std::pair<double, double>> peaks_; // largest displacement and when
    std::vector<Eigen::Vector3d> lastLow_;          // bounding box of the last level seen
    std::vector<Eigen::Vector3d> lastHigh_;
};

SPH_REGISTER_DIM_MODEL(FunctionObject, Extent, "extent");

} // namespace sph
