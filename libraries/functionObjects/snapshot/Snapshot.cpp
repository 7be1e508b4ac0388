// `snapshot`: every particle's current position and chosen fields as a gnuplot-ready table at
// given intervals, postProcessing/<name>/<name>_<time>.dat, for plots of the whole body
// without ParaView (e.g. the seed's Fig. 8, P_xx on the deformed rings).
// Keys:
//   fields        | any of: displacement velocity F P J body, or any display field of the
//                 | registry (e.g. plasticStrain, yielding: sphSolid -listTypes)   | (P)
//   writeInterval | time between snapshots [s] (0: every step)     | required here
// Columns: x y (z), then the fields' components as in `probes` (P_xx P_xy ...).
#include "core/WriteSchedule.hpp"
#include "functionObjects/FunctionObjectModel.hpp"
#include "io/AtomicFile.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <sstream>

namespace sph
{

template <int D>
class Snapshot : public FunctionObject<D>
{
public:
    static std::string description()
    {
        return "Positions and fields of every particle as text tables at intervals (plots of "
               "whole bodies without ParaView).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("writeInterval", "time between snapshots [s]; 0 writes every step")
                     .nonNegative())
            .add(Key::wordList("fields", "any of: displacement velocity F P J body, or a display "
                                         "field of the models (plasticStrain, yielding, ...)")
                     .distinct()
                     .defaultValue("(P)"));
    }

    Snapshot(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObject<D>(args.name),
          schedule_(params.real("writeInterval"), params.location("writeInterval")),
          fields_(params.wordList("fields")), folder_(args.caseDir / "postProcessing" / args.name)
    {
        std::vector<std::string> known{"displacement", "velocity", "F", "P", "J", "body"};
        const std::size_t builtIn = known.size();
        if (args.fields)
        {
            for (const auto& field : args.fields->all())
            {
                if (field.spec.isDisplay() && field.spec.kind() != FieldKind::thirdOrderTensor)
                {
                    known.push_back(field.spec.name());
                }
            }
        }
        for (std::size_t i = 0; i < fields_.size(); ++i)
        {
            const auto at = std::find(known.begin(), known.end(), fields_[i]);
            if (at == known.end())
            {
                params.fail("fields", i, "snapshot: unknown field '" + fields_[i] + "'",
                            {"Valid fields: " + joinSorted(known), didYouMean(fields_[i], known)});
            }
            registry_.push_back(static_cast<std::size_t>(at - known.begin()) < builtIn
                                    ? nullptr
                                    : args.fields->find(fields_[i]));
        }
    }

    void start(double startTime, bool restarted) override
    {
        if (!restarted)
        {
            schedule_.restart();
        }
        (void)startTime;
    }

    bool distributable() const override { return true; } // ParticleRanks

    void execute(const StepState<D>& state) override
    {
        if (!schedule_.due(state.time, state.deltaT))
        {
            return;
        }
        schedule_.checkStep(state.deltaT);
        schedule_.written(state.time, state.deltaT);
        static const char* axes[3] = {"x", "y", "z"};
        std::ostringstream out;
        out << "#";
        for (int d = 0; d < D; ++d)
        {
            out << " " << axes[d];
        }
        for (std::size_t f = 0; f < fields_.size(); ++f)
        {
            const std::string& field = fields_[f];
            if (registry_[f])
            {
                const int n = registry_[f]->components();
                for (int c = 0; c < n; ++c)
                {
                    out << " " << field;
                    if (n == D)
                    {
                        out << "_" << axes[c];
                    }
                    else if (n > 1)
                    {
                        out << "_" << axes[c / D] << axes[c % D];
                    }
                }
            }
            else if (field == "J" || field == "body")
            {
                out << " " << field;
            }
            else if (field == "F" || field == "P")
            {
                for (int i = 0; i < D; ++i)
                {
                    for (int j = 0; j < D; ++j)
                    {
                        out << " " << field << "_" << axes[i] << axes[j];
                    }
                }
            }
            else
            {
                for (int d = 0; d < D; ++d)
                {
                    out << " " << field << "_" << axes[d];
                }
            }
        }
        out << "\n";
        // Each rank's owned particles as rows (global index, then the values), joined on the
        // writer in global order: the serial table, whatever the ranks.
        const ParticleSet<D>& p = state.particles;
        const ParticleRanks& ranks = state.rankView();
        std::vector<double> rows;
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            if (!ranks.counts(a))
            {
                continue;
            }
            rows.push_back(static_cast<double>(ranks.global(a)));
            appendValues(state, a, rows);
        }
        rows = ranks.onWriter(rows);
        ++written_;
        if (!ranks.writer)
        {
            return;
        }
        std::size_t width = 1 + D;
        for (std::size_t f = 0; f < fields_.size(); ++f)
        {
            width += valueCount(f);
        }
        std::vector<std::size_t> order(rows.size() / width);
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
            return rows[i * width] < rows[j * width];
        });
        char number[32];
        for (const std::size_t i : order)
        {
            for (std::size_t k = 1; k < width; ++k)
            {
                std::snprintf(number, sizeof number, " %.9g", rows[i * width + k]);
                out << number;
            }
            out << "\n";
        }
        char time[32];
        std::snprintf(time, sizeof time, "%g", state.time);
        writeTextAtomically(folder_ / (this->name() + "_" + time + ".dat"), out.str());
    }

    std::vector<std::string> report() const override
    {
        return {this->name() + ": " + std::to_string(written_) + " snapshots in " + folder_.string()};
    }
    double nextWriteTime(double time, double deltaT) const override
    {
        return schedule_.nextAfter(time, deltaT);
    }
    void saveState(std::map<std::string, double>& state) const override
    {
        state["next"] = schedule_.next();
    }
    void restoreState(const std::map<std::string, double>& state) override
    {
        schedule_.next() = state.at("next");
    }

private:
    // How many values entry f of fields_ gives per particle.
    std::size_t valueCount(std::size_t f) const
    {
        const std::string& field = fields_[f];
        if (registry_[f])
        {
            return static_cast<std::size_t>(registry_[f]->components());
        }
        if (field == "J" || field == "body")
        {
            return 1;
        }
        return field == "F" || field == "P" ? D * D : D;
    }

    // Particle a's row after its global index: x, then each field's values.
    void appendValues(const StepState<D>& state, std::size_t a, std::vector<double>& row) const
    {
        const ParticleSet<D>& p = state.particles;
        for (int d = 0; d < D; ++d)
        {
            row.push_back(p.x[a][d]);
        }
        for (std::size_t f = 0; f < fields_.size(); ++f)
        {
            const std::string& field = fields_[f];
            if (registry_[f])
            {
                double values[9];
                registry_[f]->array->get(a, values);
                row.insert(row.end(), values, values + registry_[f]->components());
            }
            else if (field == "J")
            {
                row.push_back(p.F[a].determinant());
            }
            else if (field == "body")
            {
                row.push_back(p.body[a]);
            }
            else if (field == "F" || field == "P")
            {
                const Mat<D>& m = field == "F" ? p.F[a] : p.P[a];
                for (int i = 0; i < D; ++i)
                {
                    for (int j = 0; j < D; ++j)
                    {
                        row.push_back(m(i, j));
                    }
                }
            }
            else
            {
                const Vec<D> v = field == "velocity" ? state.velocity[a] : Vec<D>(p.x[a] - p.X[a]);
                for (int d = 0; d < D; ++d)
                {
                    row.push_back(v[d]);
                }
            }
        }
    }

    WriteSchedule schedule_;
    std::vector<std::string> fields_;
    // The registry field of each entry of fields_ (null for the built-in ones).
    std::vector<const typename ParticleFields<D>::Field*> registry_;
    std::filesystem::path folder_;
    long written_ = 0;
};

SPH_REGISTER_DIM_MODEL(FunctionObject, Snapshot, "snapshot");

} // namespace sph
