#include "RunScalars.hpp"

#include <stdexcept>
#include <type_traits>

namespace sph
{

double RunScalars::Scalar::get() const
{
    return std::visit([](auto* v) { return static_cast<double>(*v); }, value);
}

void RunScalars::Scalar::set(double number) const
{
    std::visit(
        [number](auto* v) {
            using T = std::remove_pointer_t<decltype(v)>;
            if constexpr (std::is_same_v<T, bool>)
            {
                *v = number != 0.0;
            }
            else
            {
                *v = static_cast<T>(number);
            }
        },
        value);
}

void RunScalars::checkUnique(const std::string& name) const
{
    for (const auto& scalar : scalars_)
    {
        if (scalar.name == name)
        {
            throw std::logic_error("run scalar '" + name + "' is declared twice");
        }
    }
    for (const auto& array : arrays_)
    {
        if (array.name == name)
        {
            throw std::logic_error("run array '" + name + "' is declared twice");
        }
    }
}

void RunScalars::add(const std::string& name, std::variant<double*, long*, bool*> value)
{
    checkUnique(name);
    scalars_.push_back({name, value});
}

void RunScalars::bindArray(const std::string& name, std::vector<double>& values)
{
    checkUnique(name);
    arrays_.push_back({name, &values});
}

} // namespace sph
