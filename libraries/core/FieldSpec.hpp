#pragma once
// The declaration of one per-particle quantity, made once where the quantity is owned:
//
//   static const FieldSpec& peakSpeedField()
//   {
//       static const FieldSpec spec =
//           FieldSpec::scalar("peakSpeed", "largest speed the particle has had [m/s]")
//               .restart().display();
//       return spec;
//   }
//
// Its role says what the files do with it:
//   restart   written with the full precision of the run and read back by `startFrom
//             latestTime` (the state a restart needs);
//   display   written under its physical name for ParaView (vectors padded to 3 components,
//             tensors to 3×3 with named components);
//   neither   scratch: per-particle work storage, never written (it is still resized and, in a
//             distributed run, moved with its particle).
// A field that is restart but not display is written under the name "restart:<name>", so the
// arrays a user colours by and those a restart needs are apart (README, "Output").
//
// The declaration carries no storage: ParticleFields<D> (particles/ParticleFields.hpp) holds
// or points to the arrays. Models list their declarations in `static std::vector<FieldSpec>
// fields()`, which -listTypes prints.

#include <string>
#include <vector>

namespace sph
{

enum class FieldKind
{
    integer,          // ids, flags (Int32 in files)
    scalar,           // one number
    vector,           // D components
    tensor,           // D×D components, row-major
    thirdOrderTensor  // D×D×D components (T_ijk with k fastest); restart only
};

std::string toString(FieldKind kind);

// How a D×D tensor is padded to 3×3 for display: with zeros (stresses: the in-plane part) or
// with ones on the missing diagonal (a deformation gradient in plane strain, F_zz = 1).
enum class TensorPadding
{
    zero,
    identity
};

class FieldSpec
{
public:
    static FieldSpec integer(std::string name, std::string description);
    static FieldSpec scalar(std::string name, std::string description);
    static FieldSpec vector(std::string name, std::string description);
    static FieldSpec tensor(std::string name, std::string description);
    static FieldSpec thirdOrderTensor(std::string name, std::string description);

    FieldSpec& restart();
    FieldSpec& display();
    // Display in single precision (large display-only fields; a restart field is always double).
    FieldSpec& singlePrecision();
    FieldSpec& padding(TensorPadding padding);
    // The active attribute of its kind in the files (what ParaView colours by, or uses for
    // glyphs and warping, when nothing else is chosen).
    FieldSpec& active();

    const std::string& name() const { return name_; }
    const std::string& description() const { return description_; }
    FieldKind kind() const { return kind_; }
    bool isRestart() const { return restart_; }
    bool isDisplay() const { return display_; }
    bool isScratch() const { return !restart_ && !display_; }
    bool isSinglePrecision() const { return single_; }
    TensorPadding tensorPadding() const { return padding_; }
    bool isActive() const { return active_; }
    // The array name in the files: the physical name, or "restart:<name>" for restart-only data.
    std::string fileName() const;

    // "peakSpeed  scalar, restart + display: largest speed the particle has had [m/s]"
    std::string describe() const;

    bool operator==(const FieldSpec& other) const = default;

private:
    FieldSpec(std::string name, std::string description, FieldKind kind);
    void checkConsistent() const;

    std::string name_;
    std::string description_;
    FieldKind kind_;
    bool restart_ = false;
    bool display_ = false;
    bool single_ = false;
    TensorPadding padding_ = TensorPadding::zero;
    bool active_ = false;
};

// The prefix that keeps restart-only arrays apart from the display fields.
inline constexpr const char* restartPrefix = "restart:";

} // namespace sph
