// `surfaceProfile` (2D, and a slice of a 3D slab): the free surface of a deposit, y_top(x),
// against a measured one — the final profile of a granular column collapse
// (tutorials/geomaterials/columnCollapse, columnCollapse3D). The particles of the chosen
// bodies are put into columns of width `binWidth` along x (from x = 0); a column's surface is
// its highest particle centre plus half a spacing (particles sit at the centres of their
// cells), an empty column's is 0 (the floor). In 3D, y is up as in 2D and only the particles
// whose current z lies in `slice` count: the profile of a plane-strain slab's mid-plane.
// Keys:
//   bodies     | which bodies ( ) = all                                         | ()
//   binWidth   | column width [m], > 0                                          | the spacing
//   slice      | 3D only, required: (zMin zMax) [m], zMin < zMax                | none
//   reference  | a measured profile: a text file (relative to the case) of x y pairs, comma or
//              | blank separated, '#' comments and one header line allowed      | none
// Output, at each row time: postProcessing/<name>/<name>_<time>.dat (x height [reference]
// at the column centres) and a row of <name>.dat:
//   front      the largest x of the particles plus half a spacing (the run-out) [m]
//   top        the largest height [m]
//   depositEnd the right edge of the contiguous deposit: from its first occupied column, the
//              left edge of the first empty one [m]. Ahead of a deposit thinner than one particle
//              the particles scatter with gaps; front then measures the farthest of them and
//              depositEnd where the deposit stops being continuous at this resolution.
//   largestDistance, atX  with a reference: the largest |y_top(x_r) − y_r| over the
//              reference's points (y_top interpolated linearly between column centres) and
//              where [m]
//   meanDistance, rmsDistance  with a reference: the mean and the root mean square of
//              y_top − y_ref(x) over the columns whose centres lie within the reference's x
//              range (an empty column counts as the floor) [m]. The largest distance samples
//              the surface only at the measured points, where one column-wide pit may or may
//              not fall; the mean says whether the deposit is too low or too high as a whole,
//              the rms how far its every column is (docs/results.md §5).
// summary.json: the same values at the last row.
#include "core/CaseFile.hpp"
#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "core/TextFile.hpp"
#include "functionObjects/FunctionObjectModel.hpp"
#include "functionObjects/ProfileColumns.hpp"
#include "io/AtomicFile.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>

namespace sph
{

template <int D> class SurfaceProfile : public FunctionObjectModel<D>
{
public:
    static std::string description()
    {
        return "2D, or a slice zMin <= z <= zMax of a 3D slab: the free surface y_top(x) of the "
               "chosen bodies at intervals, its front "
               "(run-out: the farthest particle), the end of the continuous deposit, its top, "
               "and against a measured profile the largest vertical distance at its points "
               "and the mean and rms of the error over the columns.";
    }
    static Schema schema()
    {
        return ProfileColumns::addKeys(FunctionObjectModel<D>::commonSchema())
            .add(Key::string("reference", "a measured profile: x y pairs [m] (file relative "
                                          "to the case)")
                     .optional())
            .add(Key::realList("slice", "3D: (zMin zMax) [m], the band of z whose particles "
                                        "make the profile (a slab's mid-plane)")
                     .optional());
    }

    SurfaceProfile(const Params& params, const typename FunctionObject<D>::Args& args)
        : FunctionObjectModel<D>(params, args)
    {
        const ProfileColumns profile = ProfileColumns::read<D>(params, args);
        bodies_ = profile.bodies;
        half_ = profile.half;
        width_ = profile.width;
        readSlice(params);
        std::vector<std::string> columns{"front", "top", "depositEnd"};
        if (params.has("reference"))
        {
            readReference(args.caseDir, params);
            columns.push_back("largestDistance");
            columns.push_back("atX");
            columns.push_back("meanDistance");
            columns.push_back("rmsDistance");
        }
        this->setColumns(columns);
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
        double front = 0.0;
        std::vector<double> height;
        for (const std::size_t b : bodies_)
        {
            for (std::size_t a = p.bodies[b].begin; a < p.bodies[b].end; ++a)
            {
                if (!ranks.counts(a) || !inSlice(p.x[a]))
                {
                    continue;
                }
                const double x = p.x[a][0];
                front = std::max(front, x + half_);
                if (x < 0.0 || !std::isfinite(x))
                {
                    continue; // left of the origin (behind a wall at x = 0): not profiled
                }
                const auto column = static_cast<std::size_t>(x / width_);
                if (column >= height.size())
                {
                    height.resize(column + 1, 0.0);
                }
                height[column] = std::max(height[column], p.x[a][1] + half_);
            }
        }
        // Over the ranks: the front and each column's height are maxima (the columns as many
        // as the widest rank's, the missing ones 0, as a serial column nothing reached).
        std::vector<double> columns{static_cast<double>(height.size())};
        ranks.maximum(columns);
        height.resize(static_cast<std::size_t>(columns[0]), 0.0);
        height.push_back(front);
        ranks.maximum(height);
        front = height.back();
        height.pop_back();
        const double top = height.empty() ? 0.0 : *std::max_element(height.begin(), height.end());
        std::vector<double> row{front, top, depositEnd(height)};
        std::ostringstream table;
        table << "# x height" << (reference_.empty() ? "" : " reference") << "\n";
        char line[96];
        for (std::size_t c = 0; c < height.size(); ++c)
        {
            const double x = (static_cast<double>(c) + 0.5) * width_;
            std::snprintf(line, sizeof line, "%.9g %.9g", x, height[c]);
            table << line;
            if (!reference_.empty())
            {
                std::snprintf(line, sizeof line, " %.9g", referenceAt(x));
                table << line;
            }
            table << "\n";
        }
        if (!reference_.empty())
        {
            double largest = -1.0;
            double at = 0.0;
            for (const auto& [x, y] : reference_)
            {
                const double distance = std::abs(heightAt(height, x) - y);
                if (distance > largest)
                {
                    largest = distance;
                    at = x;
                }
            }
            row.push_back(largest);
            row.push_back(at);
            const auto [mean, rms] = columnDistances(height);
            row.push_back(mean);
            row.push_back(rms);
        }
        last_ = row;
        char time[32];
        std::snprintf(time, sizeof time, "%g", state.time);
        if (this->writer())
        {
            writeTextAtomically(this->folder() / (this->name() + "_" + time + ".dat"), table.str());
        }
        this->writeRow(state.time, state.deltaT, row);
    }

    std::vector<std::string> report() const override
    {
        if (last_.empty())
        {
            return {};
        }
        char line[256];
        std::snprintf(line, sizeof line, "%s: front %.4g m, top %.4g m, deposit end %.4g m",
                      this->name().c_str(), last_[0], last_[1], last_[2]);
        std::string text = line;
        if (last_.size() > 3)
        {
            std::snprintf(line, sizeof line,
                          ", largest distance to the reference %.4g m at x = %.4g m", last_[3],
                          last_[4]);
            text += line;
        }
        return {text};
    }
    std::map<std::string, double> results() const override
    {
        std::map<std::string, double> values;
        if (last_.empty())
        {
            return values;
        }
        values["front"] = last_[0];
        values["top"] = last_[1];
        values["depositEnd"] = last_[2];
        if (last_.size() > 3)
        {
            values["largestDistance"] = last_[3];
            values["atX"] = last_[4];
            values["meanDistance"] = last_[5];
            values["rmsDistance"] = last_[6];
        }
        return values;
    }

private:
    void readSlice(const Params& params)
    {
        if constexpr (D == 3)
        {
            if (!params.has("slice"))
            {
                // (at the dictionary: an absent optional key has no place of its own)
                throw InputError(
                    params.source().location(),
                    "surfaceProfile: a 3D run profiles a slice of z, and 'slice' is "
                    "missing",
                    {"Add 'slice (zMin zMax);', e.g. a band one or two spacings wide about "
                     "the mid-plane of a slab between side walls."});
            }
            const std::vector<double>& slice = params.realList("slice");
            if (slice.size() != 2 || !(slice[0] < slice[1]))
            {
                params.fail(
                    "slice", "surfaceProfile: 'slice' must be two numbers zMin < zMax",
                    {"e.g. 'slice (0.045 0.055);' for the particles within 5 mm of z = 0.05."});
            }
            slice_ = {slice[0], slice[1]};
        }
        else if (params.has("slice"))
        {
            params.fail("slice",
                        "surfaceProfile: 'slice' selects a band of z, which a " +
                            std::to_string(D) + "D run does not have",
                        {"Remove 'slice' (it is for 3D slabs)."});
        }
    }
    bool inSlice(const Vec<D>& x) const
    {
        if constexpr (D == 3)
        {
            return x[2] >= slice_[0] && x[2] <= slice_[1];
        }
        return true;
    }

    double depositEnd(const std::vector<double>& height) const
    {
        std::size_t c = 0;
        while (c < height.size() && height[c] == 0.0)
        {
            ++c;
        }
        while (c < height.size() && height[c] > 0.0)
        {
            ++c;
        }
        return static_cast<double>(c) * width_;
    }

    // The mean and rms of height − reference over the columns whose centres lie within the
    // reference's x range (the columns beyond the deposit at the floor's 0).
    std::pair<double, double> columnDistances(const std::vector<double>& height) const
    {
        double sum = 0.0;
        double squares = 0.0;
        std::size_t count = 0;
        for (std::size_t c = 0;; ++c)
        {
            const double x = (static_cast<double>(c) + 0.5) * width_;
            if (x > reference_.back().first)
            {
                break;
            }
            if (x < reference_.front().first)
            {
                continue;
            }
            const double d = (c < height.size() ? height[c] : 0.0) - referenceAt(x);
            sum += d;
            squares += d * d;
            ++count;
        }
        if (count == 0)
        {
            return {0.0, 0.0};
        }
        const double n = static_cast<double>(count);
        return {sum / n, std::sqrt(squares / n)};
    }

    // The surface at x, linear between column centres (0 beyond the last column).
    double heightAt(const std::vector<double>& height, double x) const
    {
        const double s = x / width_ - 0.5;
        if (height.empty() || s >= static_cast<double>(height.size()))
        {
            return 0.0;
        }
        if (s <= 0.0)
        {
            return height.front();
        }
        const auto i = static_cast<std::size_t>(s);
        const double next = i + 1 < height.size() ? height[i + 1] : 0.0;
        return height[i] + (s - static_cast<double>(i)) * (next - height[i]);
    }
    double referenceAt(double x) const
    {
        if (x <= reference_.front().first)
        {
            return reference_.front().second;
        }
        if (x >= reference_.back().first)
        {
            return x == reference_.back().first ? reference_.back().second : 0.0;
        }
        const auto upper =
            std::upper_bound(reference_.begin(), reference_.end(), x,
                             [](double v, const auto& point) { return v < point.first; });
        const auto lower = upper - 1;
        const double t = (x - lower->first) / (upper->first - lower->first);
        return lower->second + t * (upper->second - lower->second);
    }
    void readReference(const std::filesystem::path& caseDir, const Params& params)
    {
        const std::filesystem::path file =
            caseFile(params, "reference", caseDir, "the reference profile",
                     "It is a text file of x y points (',' or blanks), named relative to the "
                     "case folder.");
        const std::string text = readTextFile(file, "reference profile", {});
        std::istringstream lines(text);
        std::string line;
        int number = 0;
        bool headerSeen = false;
        while (std::getline(lines, line))
        {
            ++number;
            std::replace(line.begin(), line.end(), ',', ' ');
            const auto first = line.find_first_not_of(" \t\r");
            if (first == std::string::npos || line[first] == '#')
            {
                continue;
            }
            std::istringstream values(line);
            double x = 0.0;
            double y = 0.0;
            if (!(values >> x >> y) || !std::isfinite(x) || !std::isfinite(y))
            {
                if (!headerSeen && reference_.empty())
                {
                    headerSeen = true; // one header line ("x,y")
                    continue;
                }
                params.fail("reference",
                            "surfaceProfile: " + file.string() + ":" + std::to_string(number) +
                                ": not an 'x y' pair of numbers",
                            {"The file holds x y pairs [m], comma or blank separated; '#' starts "
                             "a comment, one header line is allowed."});
            }
            reference_.emplace_back(x, y);
        }
        if (reference_.size() < 2)
        {
            params.fail("reference",
                        "surfaceProfile: " + file.string() + " holds fewer than two points");
        }
        std::sort(reference_.begin(), reference_.end());
    }

    std::vector<std::size_t> bodies_;
    std::array<double, 2> slice_{}; // 3D: zMin, zMax
    double half_ = 0.0;
    double width_ = 0.0;
    std::vector<std::pair<double, double>> reference_;
    std::vector<double> last_;
};

SPH_REGISTER_DIM_MODEL_FOR(FunctionObject, SurfaceProfile, "surfaceProfile", 2, 3);

} // namespace sph
