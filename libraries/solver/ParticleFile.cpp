#include "solver/ParticleFile.hpp"

#include "core/Format.hpp"
#include "core/InputError.hpp"
#include "initialConditions/generators/Generator.hpp"
#include "io/VtuChecks.hpp"

#include <algorithm>
#include <cmath>

namespace sph
{

std::filesystem::path particleFilePath(const std::filesystem::path& caseDir)
{
    return caseDir / "constant" / "particles.vtu";
}

void writeParticleFile(const std::filesystem::path& file, const InitialParticles& particles)
{
    VtuData data;
    data.points = particles.X;
    data.pointData["volume"] = VtuArray{1, particles.V, false, {}, {}};
    VtuArray body{1, {}, true, {}, {}};
    body.values.assign(particles.body.begin(), particles.body.end());
    data.pointData["bodyId"] = body;
    data.fieldData["spacing"] = VtuArray{1, {particles.spacing}, false, {}, {}};
    data.fieldData["dimension"] = VtuArray{1, {static_cast<double>(particles.dimension)}, true, {}, {}};
    data.stringFields["bodyNames"] = particles.bodyNames;
    if (!particles.particlesDictLines.empty())
    {
        data.stringFields["particlesDict"] = particles.particlesDictLines;
    }
    if (!particles.particlesDictSets.empty())
    {
        data.stringFields["particlesDictSets"] = particles.particlesDictSets;
    }
    writeVtu(file, data);
}

namespace
{

// A position the neighbour search's grid can hold: the particles span at most this many
// spacings in each direction (a 1e308 coordinate would overflow the grid's cell count).
constexpr double maxSpanInSpacings = 1.0e6;

// Where the particles overreach the grid: "" when they lie within maxSpanInSpacings of their
// median in every direction, otherwise the particle farthest out and by how much.
std::string spanProblem(const InitialParticles& particles)
{
    const std::size_t n = particles.size();
    for (int d = 0; d < particles.dimension && n > 0; ++d)
    {
        const auto coordinate = [&](std::size_t a)
        { return particles.X[3 * a + static_cast<std::size_t>(d)]; };
        std::vector<double> sorted(n);
        for (std::size_t a = 0; a < n; ++a)
        {
            sorted[a] = coordinate(a);
        }
        const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(n / 2);
        std::nth_element(sorted.begin(), middle, sorted.end());
        std::size_t farthest = 0;
        for (std::size_t a = 1; a < n; ++a)
        {
            if (std::abs(coordinate(a) - *middle) > std::abs(coordinate(farthest) - *middle))
            {
                farthest = a;
            }
        }
        const double reach = maxSpanInSpacings * particles.spacing;
        if (!(std::abs(coordinate(farthest) - *middle) <= reach))
        {
            const std::string axis(1, "xyz"[d]);
            return "particle " + std::to_string(farthest) + " has " + axis + " = " +
                   formatNumber(coordinate(farthest)) + ", but the particles must lie within " +
                   formatNumber(maxSpanInSpacings) + " spacings (" + formatNumber(reach) +
                   " m) of their middle, " + axis + " = " + formatNumber(*middle);
        }
    }
    return {};
}

} // namespace

InitialParticles readParticleFile(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file))
    {
        throw InputError("cannot find the initial particles '" + file.string() + "'",
                         {"Run sphParticles first: it builds them from system/particlesDict."});
    }
    const VtuData data = readVtu(file);
    const VtuChecks checks(data, file.string(),
                           "The file is damaged or was not written by sphParticles; run "
                           "sphParticles again.");
    if (data.pointCount() == 0)
    {
        checks.fail("it holds no particles");
    }
    InitialParticles particles;
    const auto names = data.stringFields.find("bodyNames");
    if (names == data.stringFields.end() || names->second.empty())
    {
        checks.fail("it has no field data 'bodyNames' naming the bodies");
    }
    particles.bodyNames = names->second;
    // What made them, when the file says (solver/ParticleProvenance checks it).
    const auto strings = [&](const char* name)
    {
        const auto it = data.stringFields.find(name);
        return it == data.stringFields.end() ? std::vector<std::string>() : it->second;
    };
    particles.particlesDictLines = strings("particlesDict");
    particles.particlesDictSets = strings("particlesDictSets");
    const VtuArray& dimension = checks.fieldArray("dimension", 1);
    checks.wholeNumbers("dimension", dimension, 1, 3, "the space dimension");
    particles.dimension = static_cast<int>(dimension.values[0]);
    const VtuArray& spacing = checks.fieldArray("spacing", 1);
    checks.positive("spacing", spacing);
    particles.spacing = spacing.values[0];
    checks.finitePoints();
    particles.X = data.points;
    const VtuArray& volume = checks.pointArray("volume", 1);
    checks.positive("volume", volume);
    particles.V = volume.values;
    const VtuArray& bodyId = checks.pointArray("bodyId", 1);
    const std::size_t bodies = particles.bodyNames.size();
    checks.wholeNumbers("bodyId", bodyId, 0, static_cast<double>(bodies - 1),
                        "a body index; field data 'bodyNames' names " + std::to_string(bodies) +
                            (bodies == 1 ? " body" : " bodies"));
    particles.body.assign(bodyId.values.begin(), bodyId.values.end());
    if (const std::string problem = spanProblem(particles); !problem.empty())
    {
        checks.fail(problem);
    }
    return particles;
}

namespace
{

template <int D>
InitialParticles generate(const Dictionary& dict, const std::filesystem::path& caseDir)
{
    InitialParticles particles;
    particles.dimension = D;
    const Entry* firstBody = nullptr;
    for (const Entry& entry : dict.entries())
    {
        if (entry.referenced() && !entry.isDict())
        {
            continue; // a definition used elsewhere with $name, e.g. spacing 1e-3;
        }
        if (!entry.isDict())
        {
            throw InputError(entry.keyLocation(),
                             "'" + entry.key() + "' in system/particlesDict must be a body { type "
                             "...; }",
                             {"Each top-level entry of particlesDict is one body, e.g. bar { type "
                              "line; start 0; end 0.1333; n 40; }"});
        }
        const auto generator = selectModel<Generator<D>>(entry.dict(), {caseDir}, D);
        const GeneratedBody<D> body = generator->generate();
        if (body.X.empty())
        {
            throw InputError(entry.keyLocation(),
                             "body '" + entry.key() + "' has no particles",
                             {"The shape is smaller than one spacing; check its size and "
                              "'spacing'."});
        }
        if (!firstBody)
        {
            firstBody = &entry;
            particles.spacing = body.spacing;
        }
        else if (std::abs(body.spacing - particles.spacing) > 1e-9 * particles.spacing)
        {
            throw InputError(entry.keyLocation(),
                             "body '" + entry.key() + "' has spacing " +
                                 std::to_string(body.spacing) + " but '" + firstBody->key() +
                                 "' has " + std::to_string(particles.spacing),
                             {"sphSolid uses one smoothing length h = hOverDx * spacing for the "
                              "whole case: give every body the same spacing."});
        }
        const int id = static_cast<int>(particles.bodyNames.size());
        particles.bodyNames.push_back(entry.key());
        for (std::size_t i = 0; i < body.X.size(); ++i)
        {
            for (int d = 0; d < 3; ++d)
            {
                particles.X.push_back(d < D ? body.X[i][d] : 0.0);
            }
            particles.V.push_back(body.V[i]);
            particles.body.push_back(id);
        }
    }
    if (particles.bodyNames.empty())
    {
        throw InputError(dict.location(), "system/particlesDict defines no body",
                         {"Add one, e.g. bar { type line; start 0; end 0.1333; n 40; }"});
    }
    if (const std::string problem = spanProblem(particles); !problem.empty())
    {
        throw InputError(dict.location(), problem,
                         {"Check the bodies' positions (and the points of any imported .vtu)."});
    }
    return particles;
}

} // namespace

InitialParticles generateParticles(const Dictionary& particlesDict, int dimension,
                                   const std::filesystem::path& caseDir)
{
    switch (dimension)
    {
    case 1:
        return generate<1>(particlesDict, caseDir);
    case 2:
        return generate<2>(particlesDict, caseDir);
    default:
        return generate<3>(particlesDict, caseDir);
    }
}

} // namespace sph
