#include "FieldSpec.hpp"

#include <cctype>
#include <stdexcept>

namespace sph
{

std::string toString(FieldKind kind)
{
    switch (kind)
    {
    case FieldKind::integer: return "integer";
    case FieldKind::scalar: return "scalar";
    case FieldKind::vector: return "vector";
    case FieldKind::tensor: return "tensor";
    case FieldKind::thirdOrderTensor: return "third-order tensor";
    }
    return "?";
}

FieldSpec::FieldSpec(std::string name, std::string description, FieldKind kind)
    : name_(std::move(name)), description_(std::move(description)), kind_(kind)
{
    // Names become VTK array names and dictionary words: keep them identifiers.
    bool valid = !name_.empty() && std::isalpha(static_cast<unsigned char>(name_[0]));
    for (const char c : name_)
    {
        valid = valid && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    }
    if (!valid)
    {
        throw std::logic_error("field name '" + name_ + "' is not an identifier");
    }
}

FieldSpec FieldSpec::integer(std::string name, std::string description)
{
    return FieldSpec(std::move(name), std::move(description), FieldKind::integer);
}
FieldSpec FieldSpec::scalar(std::string name, std::string description)
{
    return FieldSpec(std::move(name), std::move(description), FieldKind::scalar);
}
FieldSpec FieldSpec::vector(std::string name, std::string description)
{
    return FieldSpec(std::move(name), std::move(description), FieldKind::vector);
}
FieldSpec FieldSpec::tensor(std::string name, std::string description)
{
    return FieldSpec(std::move(name), std::move(description), FieldKind::tensor);
}
FieldSpec FieldSpec::thirdOrderTensor(std::string name, std::string description)
{
    return FieldSpec(std::move(name), std::move(description), FieldKind::thirdOrderTensor);
}

FieldSpec& FieldSpec::restart()
{
    restart_ = true;
    checkConsistent();
    return *this;
}

FieldSpec& FieldSpec::display()
{
    display_ = true;
    checkConsistent();
    return *this;
}

FieldSpec& FieldSpec::singlePrecision()
{
    single_ = true;
    checkConsistent();
    return *this;
}

FieldSpec& FieldSpec::padding(TensorPadding padding)
{
    padding_ = padding;
    return *this;
}

FieldSpec& FieldSpec::active()
{
    active_ = true;
    checkConsistent();
    return *this;
}

void FieldSpec::checkConsistent() const
{
    const auto fail = [&](const std::string& why) {
        throw std::logic_error("field '" + name_ + "': " + why);
    };
    if (restart_ && single_)
    {
        fail("restart data must be written in double precision");
    }
    if (display_ && kind_ == FieldKind::thirdOrderTensor)
    {
        fail("third-order tensors have no display form");
    }
    if (active_ && !display_)
    {
        fail("only a display field can be the active attribute");
    }
    if (active_ && kind_ == FieldKind::integer)
    {
        fail("an integer field cannot be the active attribute");
    }
}

std::string FieldSpec::fileName() const
{
    return display_ || !restart_ ? name_ : restartPrefix + name_;
}

std::string FieldSpec::describe() const
{
    std::string role = restart_ && display_ ? "restart + display"
                       : restart_           ? "restart"
                       : display_           ? "display"
                                            : "scratch";
    return name_ + "  " + toString(kind_) + ", " + role + ": " + description_;
}

} // namespace sph
