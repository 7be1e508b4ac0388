// `failureLine` (2D): the boundary, in the initial configuration, between the material that has
// moved more than `threshold` and the material that has not — the failure surface of a granular
// column collapse (tutorials/geomaterials/columnCollapse), measured in experiments from the
// rods that did not move.
// The particles of the chosen bodies are put into columns of width `binWidth` along the initial
// X (from X = 0). In each column, from the floor up, the material is unmoved up to the bottom
// of the cell (half a spacing below the centre) of its lowest moved particle: that height is the
// column's failure height Y_f; a column with no moved particle has Y_f at its top, one whose
// lowest particle moved has Y_f at its bottom.
// Keys:
//   bodies     | which bodies ( ) = all                                         | ()
//   threshold  | displacement |x − X| that counts as moved [m], > 0             | required
//   binWidth   | column width [m], > 0                                          | the spacing
// Output, at each row time: postProcessing/<name>/<name>_<time>.dat (X failureHeight bottom
// top at the column centres; columns no particle starts in are left out) and a row of
// <name>.dat:
//   toe          the X where the unmoved base ends on the floor: the left edge of the first
//                column (from X = 0) whose lowest particle moved [m]
//   angle        the least-squares slope of the failure heights strictly inside their columns
//                (bottom < Y_f < top), in degrees, positive for a line falling with X [deg]
//   unmovedArea  Σ V0 of the particles that have not moved [m² per metre]
// summary.json: the same values at the last row.
#include "functionObjects/FunctionObjectModel.hpp"
#include "functionObjects/ProfileColumns.hpp"
#include "io/AtomicFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace sph
{

template <int D>
class FailureLine : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "2D: the failure line in the initial configuration, between the material that "
               "moved more than a threshold and the material that did not, per column of "
               "initial X; its toe, its angle and the unmoved area.";
    }
    static Schema schema()
    {
        return ProfileColumns::addKeys(FunctionObjectModel<D>::commonSchema())
            .add(Key::real("threshold", "displacement |x - X| that counts as moved [m], e.g. "
                                        "1e-3")
                     .positive());
    }

    FailureLine(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args), threshold_(params.real("threshold"))
    {
        const ProfileColumns profile = ProfileColumns::read<D>(params, args);
        bodies_ = profile.bodies;
        half_ = profile.half;
        width_ = profile.width;
        this->setColumns({"toe", "angle", "unmovedArea"});
    }

    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        if (!this->rowDue(state.time, state.deltaT))
        {
            return;
        }
        const ParticleSet<D>& p = state.particles;
        const ParticleRanks& ranks = state.rankView();
        const double none = std::numeric_limits<double>::lowest();
        // Per column, as maxima (so that the ranks combine them with one operation):
        // −bottom, top, −(lowest moved cell bottom); and the unmoved area as a sum.
        std::vector<double> negBottom;
        std::vector<double> top;
        std::vector<double> negMoved;
        double unmoved = 0.0;
        for (const std::size_t b : bodies_)
        {
            for (std::size_t a = p.bodies[b].begin; a < p.bodies[b].end; ++a)
            {
                if (!ranks.counts(a))
                {
                    continue;
                }
                const double X = p.X[a][0];
                if (X < 0.0)
                {
                    continue; // behind a wall at X = 0: not profiled
                }
                const auto column = static_cast<std::size_t>(X / width_);
                if (column >= top.size())
                {
                    negBottom.resize(column + 1, none);
                    top.resize(column + 1, none);
                    negMoved.resize(column + 1, none);
                }
                const double Y = p.X[a][1];
                negBottom[column] = std::max(negBottom[column], -(Y - half_));
                top[column] = std::max(top[column], Y + half_);
                const bool moved = !((p.x[a] - p.X[a]).norm() <= threshold_); // NaN: moved
                if (moved)
                {
                    negMoved[column] = std::max(negMoved[column], -(Y - half_));
                }
                else
                {
                    unmoved += p.V0[a];
                }
            }
        }
        std::vector<double> columns{static_cast<double>(top.size())};
        ranks.maximum(columns);
        const auto n = static_cast<std::size_t>(columns[0]);
        negBottom.resize(n, none);
        top.resize(n, none);
        negMoved.resize(n, none);
        ranks.maximum(negBottom);
        ranks.maximum(top);
        ranks.maximum(negMoved);
        std::vector<double> area{unmoved};
        ranks.sum(area);
        unmoved = area[0];

        std::ostringstream table;
        table << "# X failureHeight bottom top\n";
        char line[128];
        double toe = std::numeric_limits<double>::quiet_NaN();
        double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, count = 0.0;
        for (std::size_t c = 0; c < n; ++c)
        {
            if (top[c] == none)
            {
                continue; // no particle starts in this column
            }
            const double X = (static_cast<double>(c) + 0.5) * width_;
            const double bottom = -negBottom[c];
            const double failure = negMoved[c] == none ? top[c] : -negMoved[c];
            std::snprintf(line, sizeof line, "%.9g %.9g %.9g %.9g\n", X, failure, bottom, top[c]);
            table << line;
            if (std::isnan(toe) && failure <= bottom)
            {
                toe = static_cast<double>(c) * width_;
            }
            if (failure > bottom && failure < top[c])
            {
                sx += X;
                sy += failure;
                sxx += X * X;
                sxy += X * failure;
                count += 1.0;
            }
        }
        if (std::isnan(toe))
        {
            toe = static_cast<double>(n) * width_; // no column's base moved
        }
        const double denominator = count * sxx - sx * sx;
        const double angle = count >= 2.0 && denominator > 0.0
                                 ? std::atan(-(count * sxy - sx * sy) / denominator) * 180.0 / M_PI
                                 : std::numeric_limits<double>::quiet_NaN();
        last_ = {toe, angle, unmoved};
        char time[32];
        std::snprintf(time, sizeof time, "%g", state.time);
        if (this->writer())
        {
            writeTextAtomically(this->folder() / (this->name() + "_" + time + ".dat"), table.str());
        }
        this->writeRow(state.time, state.deltaT, last_);
    }

    std::vector<std::string> report() const override
    {
        if (last_.empty())
        {
            return {};
        }
        char line[256];
        std::snprintf(line, sizeof line,
                      "%s: toe %.4g m, angle %.3g deg, unmoved area %.4g m^2 (moved: |x - X| > "
                      "%g m)",
                      this->name().c_str(), last_[0], last_[1], last_[2], threshold_);
        return {line};
    }
    std::map<std::string, double> results() const override
    {
        if (last_.empty())
        {
            return {};
        }
        return {{"toe", last_[0]}, {"angle", last_[1]}, {"unmovedArea", last_[2]}};
    }

private:
    double threshold_;
    std::vector<std::size_t> bodies_;
    double half_ = 0.0;
    double width_ = 0.0;
    std::vector<double> last_;
};

SPH_REGISTER_DIM_MODEL_FOR(FunctionObject, FailureLine, "failureLine", 2);

} // namespace sph
