// `none`: bodies pass through each other; no contact search, no cost. Keys: none.
#include "contact/Contact.hpp"

namespace sph
{

template <int D>
class NoContact : public Contact<D>
{
public:
    static std::string description() { return "No contact between bodies (no search, no cost)."; }
    static Schema schema() { return Schema(); }
    NoContact(const Params&, const typename Contact<D>::Args&) {}

    bool active() const override { return false; }
    void apply(ContactState<D>&, std::vector<Vec<D>>&) override {}
};

SPH_REGISTER_DIM_MODEL(Contact, NoContact, "none");

} // namespace sph
