#include "solver/ParticleFile.hpp"

#include "core/InputError.hpp"
#include "initialConditions/generators/Generator.hpp"
#include "io/VtuFile.hpp"

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
    writeVtu(file, data);
}

InitialParticles readParticleFile(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file))
    {
        throw InputError("cannot find the initial particles '" + file.string() + "'",
                         {"Run sphParticles first: it builds them from system/particlesDict."});
    }
    const VtuData data = readVtu(file);
    const auto need = [&](const std::map<std::string, VtuArray>& arrays, const std::string& name) {
        const auto found = arrays.find(name);
        if (found == arrays.end())
        {
            throw InputError("'" + file.string() + "' has no array '" + name + "'",
                             {"It was not written by sphParticles; run sphParticles again."});
        }
        return found->second;
    };
    InitialParticles particles;
    particles.X = data.points;
    particles.V = need(data.pointData, "volume").values;
    for (double id : need(data.pointData, "bodyId").values)
    {
        particles.body.push_back(static_cast<int>(id));
    }
    particles.spacing = need(data.fieldData, "spacing").values.at(0);
    particles.dimension = static_cast<int>(need(data.fieldData, "dimension").values.at(0));
    const auto names = data.stringFields.find("bodyNames");
    if (names == data.stringFields.end())
    {
        throw InputError("'" + file.string() + "' has no field 'bodyNames'",
                         {"Run sphParticles again."});
    }
    particles.bodyNames = names->second;
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
