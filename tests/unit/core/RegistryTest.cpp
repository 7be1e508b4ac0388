#include "core/Registry.hpp"
#include "support/TestSupport.hpp"

using namespace sph;
using sph::test::parse;
using sph::test::requireInputError;

namespace
{

// A dimension-independent test family.
class Widget
{
public:
    static constexpr const char* family = "testWidget";
    static constexpr int dimension = 0;
    struct Args
    {
        double scale = 1.0;
    };
    virtual ~Widget() = default;
    virtual double value() const = 0;
};

class Sprocket : public Widget
{
public:
    static std::string description() { return "A sprocket."; }
    static Schema schema() { return Schema().add(Key::real("teeth", "tooth count").positive()); }
    Sprocket(const Params& p, const Args& args) : value_(p.real("teeth") * args.scale) {}
    double value() const override { return value_; }

private:
    double value_;
};

class Gear : public Widget
{
public:
    static std::string description() { return "A gear."; }
    static Schema schema() { return Schema(); }
    Gear(const Params&, const Args&) {}
    double value() const override { return 1.0; }
};

SPH_REGISTER_MODEL(Widget, Sprocket, "sprocket");
SPH_REGISTER_MODEL(Widget, Gear, "gear");

// A dimension-templated test family, with one model only in 2D.
template <int D>
class Gadget
{
public:
    static constexpr const char* family = "testGadget";
    static constexpr int dimension = D;
    struct Args
    {
    };
    virtual ~Gadget() = default;
    virtual int dim() const = 0;
};

template <int D>
class Lever : public Gadget<D>
{
public:
    static std::string description() { return "A lever."; }
    static Schema schema() { return Schema().add(Key::vector("pivot", "pivot point")); }
    Lever(const Params& p, const typename Gadget<D>::Args&) : size_(p.vector("pivot").size()) {}
    int dim() const override { return static_cast<int>(size_) * 10 + D; }

private:
    std::size_t size_;
};

template <int D>
class Plane : public Gadget<D>
{
public:
    static std::string description() { return "Only in 2D."; }
    static Schema schema() { return Schema(); }
    Plane(const Params&, const typename Gadget<D>::Args&) {}
    int dim() const override { return D; }
};

SPH_REGISTER_DIM_MODEL(Gadget, Lever, "lever");
SPH_REGISTER_DIM_MODEL_FOR(Gadget, Plane, "plane", 2);

// A family whose models are summarised from their registered name and params.
class Knob : public RegisteredModel
{
public:
    static constexpr const char* family = "testKnob";
    static constexpr int dimension = 0;
    struct Args
    {
    };
};

class Dial : public Knob
{
public:
    static std::string description() { return "A dial."; }
    static Schema schema()
    {
        return Schema()
            .add(Key::real("turns", "turns").defaultValue("1.5"))
            .add(Key::vector("axis", "axis").size(2))
            .add(Key::word("label", "a label").optional());
    }
    Dial(const Params& p, const Args&) : turns_(p.real("turns")) {}

private:
    std::vector<std::string> summaryExtras() const override
    {
        return {"degrees=" + std::to_string(static_cast<int>(360 * turns_))};
    }
    double turns_;
};

class Toggle : public Knob
{
public:
    static std::string description() { return "A toggle."; }
    static Schema schema() { return Schema(); }
    Toggle(const Params&, const Args&) {}
};

SPH_REGISTER_MODEL(Knob, Dial, "dial");
SPH_REGISTER_MODEL(Knob, Toggle, "toggle");

} // namespace

TEST_CASE("registry: one-line registration, sorted names", "[registry]")
{
    CHECK(Registry<Widget>::names() == std::vector<std::string>{"gear", "sprocket"});
    const ModelRecord* record = RegistryStore::instance().find("testWidget", "sprocket");
    REQUIRE(record);
    CHECK(record->description == "A sprocket.");
    CHECK_THAT(record->sourceFile, Catch::EndsWith("RegistryTest.cpp"));
    CHECK(Registry<Gadget<2>>::names() == std::vector<std::string>{"lever", "plane"});
    CHECK(Registry<Gadget<1>>::names() == std::vector<std::string>{"lever"});
}

TEST_CASE("registry: selectModel validates and builds by name", "[registry]")
{
    const auto dict = parse("w { type sprocket; teeth 12; }\n");
    const auto widget = selectModel<Widget>(dict->find("w")->dict(), Widget::Args{2.0}, 0);
    CHECK(widget->value() == 24.0);

    const auto gadgets = parse("g { type lever; pivot (0 0 0); }\n");
    CHECK(selectModel<Gadget<3>>(gadgets->find("g")->dict(), {}, 3)->dim() == 33);
}

TEST_CASE("registry: a model's summary is its name and its params as written", "[registry]")
{
    // Defaults included, as declared; optional keys without a value left out; then the model's
    // derived figures.
    const auto dict = parse("k { type dial; axis (1   0.5e0); }\n");
    const auto dial = selectModel<Knob>(dict->find("k")->dict(), {}, 0);
    CHECK(dial->typeName() == "dial");
    CHECK(dial->summary() == "dial(turns=1.5, axis=(1 0.5e0), degrees=540)");
    const auto named = parse("k { type dial; turns 2; axis (0 1); label x; }\n");
    CHECK(selectModel<Knob>(named->find("k")->dict(), {}, 0)->summary() ==
          "dial(turns=2, axis=(0 1), label=x, degrees=720)");
    // No parameters, no figures: the bare name.
    const auto toggle = parse("k { type toggle; }\n");
    CHECK(selectModel<Knob>(toggle->find("k")->dict(), {}, 0)->summary() == "toggle");
}

TEST_CASE("registry: a key that selects a model lists the family's types when printed",
          "[registry][schema]")
{
    const Schema schema =
        Schema().add(Key::dict("knob", "a knob { type ...; }").selects("testKnob"));
    CHECK(schema.describe()[0] == "knob  (dictionary, required)  a knob { type dial | toggle; }");
    // A model registered after the schema was declared (as by a library loaded from a case's
    // `libs`) is listed too: the names are looked up when the text is printed.
    Registry<Knob>::add(
        "slider", "A slider.", [] { return Schema(); }, "plugin/Slider.cpp",
        [](const Params&, const Knob::Args&) -> std::unique_ptr<Knob> { return nullptr; }, nullptr);
    CHECK_THAT(schema.describe()[0], Catch::EndsWith("a knob { type dial | slider | toggle; }"));
    const auto missing = parse("type x;\n");
    const std::string text = requireInputError([&] { schema.validate(*missing, "testDict"); }, 0, 0,
                                               "missing required key 'knob'");
    CHECK_THAT(text, Catch::Contains("'knob': a knob { type dial | slider | toggle; }"));
    // Without the syntax in the doc, it is appended.
    CHECK(Key::dict("k", "a knob").selects("testKnob").doc() ==
          "a knob { type dial | slider | toggle; ... }");
}

TEST_CASE("registry: unknown names list the valid ones with a suggestion", "[registry][errors]")
{
    const auto dict = parse("w\n{\n    type  sprockett;\n}\n", "system/sphSchemes");
    const std::string text = requireInputError(
        [&] { selectModel<Widget>(dict->find("w")->dict(), {}, 0); }, 3, 11,
        "unknown testWidget type 'sprockett'");
    CHECK_THAT(text, Catch::Contains("Valid testWidget types (2): gear, sprocket"));
    CHECK_THAT(text, Catch::Contains("Did you mean 'sprocket'?"));
    CHECK_THAT(text, Catch::Contains("system/controlDict 'libs'"));
    CHECK_THAT(text, Catch::Contains("    type  sprockett;\n              ^~~~~~~~~\n"));
}

TEST_CASE("registry: missing type and model errors from the schema", "[registry][errors]")
{
    const auto noType = parse("w { teeth 3; }\n");
    const std::string text = requireInputError(
        [&] { selectModel<Widget>(noType->find("w")->dict(), {}, 0); }, 1, 1,
        "missing required key 'type' in 'w'");
    CHECK_THAT(text, Catch::Contains("Valid testWidget types (2): gear, sprocket"));

    const auto badKey = parse("w { type sprocket; teeth 3; color red; }\n");
    requireInputError([&] { selectModel<Widget>(badKey->find("w")->dict(), {}, 0); }, 1, 29,
                      "unknown key 'color' in 'w'");
}

TEST_CASE("registry: a model missing in this dimension says where it exists", "[registry][errors]")
{
    const auto dict = parse("g { type plane; }\n");
    const std::string text = requireInputError(
        [&] { selectModel<Gadget<1>>(dict->find("g")->dict(), {}, 1); }, 1, 10,
        "testGadget type 'plane' is not available in 1D");
    CHECK_THAT(text, Catch::Contains("'plane' exists for 2D."));
}

TEST_CASE("registry: a duplicate name is recorded naming both sources", "[registry][errors]")
{
    RegistryStore::instance().takeConflicts();
    Registry<Widget>::add(
        "gear", "Another gear.", [] { return Schema(); }, "elsewhere/OtherGear.cpp",
        [](const Params&, const Widget::Args&) -> std::unique_ptr<Widget> { return nullptr; },
        nullptr);
    const auto conflicts = RegistryStore::instance().takeConflicts();
    REQUIRE(conflicts.size() == 1);
    CHECK_THAT(conflicts[0], Catch::Contains("testWidget type 'gear' is registered twice"));
    CHECK_THAT(conflicts[0], Catch::Contains("RegistryTest.cpp"));
    CHECK_THAT(conflicts[0], Catch::Contains("elsewhere/OtherGear.cpp"));
    // The first registration stays in force.
    CHECK(RegistryStore::instance().find("testWidget", "gear")->description == "A gear.");
}
