#pragma once
// What a model built by the registry knows about itself: the name it was registered under and
// its parameters as the user wrote them (defaults included). The one-line summary of the run
// header and postProcessing/summary.json is derived from them,
//
//   vidal(beta=0.1)      neoHookean(rho=1000, mu=0.3571e6, kappa=1.67e6, c=46.3264 m/s)
//
// so a model does not repeat its own name and keys. A family's interface class derives from
// RegisteredModel (Registry<Base>::create fills it in); a model adds figures derived from its
// parameters or the case (a wave speed, the smoothing length) by overriding summaryExtras().

#include <string>
#include <vector>

namespace sph
{

template <class Base>
class Registry;

class RegisteredModel
{
public:
    virtual ~RegisteredModel() = default;

    // The registered name ("neoHookean"); empty for a model not built by the registry.
    const std::string& typeName() const { return typeName_; }

    // "name(key=value, ..., extra, ...)": the parameters in declaration order, then the derived
    // figures; the bare name when there are neither.
    std::string summary() const
    {
        std::string inside = parameters_;
        for (const std::string& extra : summaryExtras())
        {
            inside += (inside.empty() ? "" : ", ") + extra;
        }
        return inside.empty() ? typeName_ : typeName_ + "(" + inside + ")";
    }

protected:
    // Figures the parameters do not show, e.g. {"c=173.205 m/s"}.
    virtual std::vector<std::string> summaryExtras() const { return {}; }

private:
    template <class Base>
    friend class Registry;

    std::string typeName_;
    std::string parameters_; // "key=value, ..." (Params::summary)
};

} // namespace sph
