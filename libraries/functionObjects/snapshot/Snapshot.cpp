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

#include <cstdio>
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
        const ParticleSet<D>& p = state.particles;
        char number[32];
        const auto put = [&](double value) {
            std::snprintf(number, sizeof number, " %.9g", value);
            out << number;
        };
        for (std::size_t a = 0; a < p.size(); ++a)
        {
            for (int d = 0; d < D; ++d)
            {
                put(p.x[a][d]);
            }
            for (std::size_t f = 0; f < fields_.size(); ++f)
            {
                const std::string& field = fields_[f];
                if (registry_[f])
                {
                    double values[9];
                    registry_[f]->array->get(a, values);
                    for (int c = 0; c < registry_[f]->components(); ++c)
                    {
                        put(values[c]);
                    }
                }
                else if (field == "J")
                {
                    put(p.F[a].determinant());
                }
                else if (field == "body")
                {
                    put(p.body[a]);
                }
                else if (field == "F" || field == "P")
                {
                    const Mat<D>& m = field == "F" ? p.F[a] : p.P[a];
                    for (int i = 0; i < D; ++i)
                    {
                        for (int j = 0; j < D; ++j)
                        {
                            put(m(i, j));
                        }
                    }
                }
                else
                {
                    const Vec<D> v = field == "velocity" ? state.velocity[a] : Vec<D>(p.x[a] - p.X[a]);
                    for (int d = 0; d < D; ++d)
                    {
                        put(v[d]);
                    }
                }
            }
            out << "\n";
        }
        char time[32];
        std::snprintf(time, sizeof time, "%g", state.time);
        writeTextAtomically(folder_ / (this->name() + "_" + time + ".dat"), out.str());
        ++written_;
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
    WriteSchedule schedule_;
    std::vector<std::string> fields_;
    // The registry field of each entry of fields_ (null for the built-in ones).
    std::vector<const typename ParticleFields<D>::Field*> registry_;
    std::filesystem::path folder_;
    long written_ = 0;
};

SPH_REGISTER_DIM_MODEL(FunctionObject, Snapshot, "snapshot");

} // namespace sph
