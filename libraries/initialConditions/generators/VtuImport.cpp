// `vtu`: imports a point set from a VTK .vtu file (e.g. made in ParaView or another mesher).
// Points beyond the case dimension must be zero; a point array named by `volumeArray` gives
// the volumes, otherwise every particle gets spacing^dim.
// Keys:
//   file        | the .vtu file, relative to the case folder            | required
//   spacing     | particle spacing [m] (sets h = hOverDx · spacing)      | required
//   volumeArray | name of a point array holding the volumes              | optional
#include "initialConditions/generators/Generator.hpp"
#include "io/VtuChecks.hpp"

#include <cmath>

namespace sph
{

template <int D>
class VtuImport : public Generator<D>
{
public:
    static std::string description()
    {
        return "Import a point set from a .vtu file (volumes from a point array or "
               "spacing^dim).";
    }
    static Schema schema()
    {
        return Schema()
            .add(Key::string("file", "the .vtu file, relative to the case folder"))
            .add(Key::real("spacing", "particle spacing [m]").positive())
            .add(Key::word("volumeArray", "name of a point array holding the volumes").optional());
    }
    VtuImport(const Params& p, const typename Generator<D>::Args& args)
        : file_(args.caseDir / p.string("file")), spacing_(p.real("spacing")),
          volumeArray_(p.has("volumeArray") ? p.word("volumeArray") : "")
    {
        if (!std::filesystem::is_regular_file(file_))
        {
            p.fail("file", "vtu: cannot find '" + file_.string() + "'",
                   {"The path is relative to the case folder."});
        }
        generated_ = read(p);
    }
    GeneratedBody<D> generate() const override { return generated_; }

private:
    GeneratedBody<D> read(const Params& p) const
    {
        const VtuData data = readVtu(file_);
        const VtuChecks checks(data, file_.string(),
                               "The 'vtu' generator of system/particlesDict imports it: every "
                               "coordinate and volume must be finite, every volume > 0.");
        checks.finitePoints();
        GeneratedBody<D> body;
        body.spacing = spacing_;
        const VtuArray* volumes = nullptr;
        if (!volumeArray_.empty())
        {
            if (data.pointData.count(volumeArray_) == 0)
            {
                p.fail("volumeArray",
                       "vtu: '" + file_.string() + "' has no point array '" + volumeArray_ + "'");
            }
            volumes = &checks.pointArray(volumeArray_, 1);
            checks.positive(volumeArray_, *volumes);
        }
        for (std::size_t i = 0; i < data.pointCount(); ++i)
        {
            Vec<D> x;
            for (int d = 0; d < 3; ++d)
            {
                const double value = data.points[3 * i + static_cast<std::size_t>(d)];
                if (d < D)
                {
                    x[d] = value;
                }
                else if (value != 0.0)
                {
                    p.fail("file", "vtu: point " + std::to_string(i) + " of '" + file_.string() +
                                       "' has a non-zero coordinate beyond the case's " +
                                       std::to_string(D) + " dimensions");
                }
            }
            body.X.push_back(x);
            body.V.push_back(volumes ? volumes->values[i] : std::pow(spacing_, D));
        }
        if (body.X.empty())
        {
            p.fail("file", "vtu: '" + file_.string() + "' holds no points");
        }
        return body;
    }

    std::filesystem::path file_;
    double spacing_;
    std::string volumeArray_;
    GeneratedBody<D> generated_;
};

SPH_REGISTER_DIM_MODEL(Generator, VtuImport, "vtu");

} // namespace sph
