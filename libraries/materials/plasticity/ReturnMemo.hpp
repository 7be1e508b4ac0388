#pragma once
// The last return map of each particle, remembered (issue 30: plastic materials at the cost of
// elastic ones). One level asks a particle's return three times at the same F from the same
// committed state: the force evaluation, the time step's wave-speed bound and the commit
// (docs/theory/plasticity.md §P7). The force evaluation stores what the other two need (the
// largest |τ|, the flow, the state to commit); they find it when F and the committed state are
// bitwise those it was computed from, and compute the return themselves otherwise (a restart,
// a particle that arrived from another rank, a test calling them alone). Same inputs, same
// function: the results are bit for bit those without the memo.
//
// Storage: scratch particle fields (never written, resized and moved with the particles), 19
// numbers per particle in 2D, 34 in 3D; only a plastic material declares them.

#include "materials/plasticity/PlasticHistory.hpp"

#include <cstring>
#include <limits>

namespace sph
{

template <int D>
class ReturnMemo
{
public:
    // What the wave-speed bound and the commit need of a return.
    struct Entry
    {
        double waveModulus = 0.0; // M + max |τ| of (P2.5)
        PlasticFlow flow;
        PlasticState<D> next;
    };

    explicit ReturnMemo(ParticleFields<D>& fields)
        : F_(fields.template declare<Mat<D>>(spec("F"), Mat<D>::Constant(nan()))),
          committedCp_(fields.template declare<Mat<D>>(spec("CommittedCp"), Mat<D>::Identity())),
          nextCp_(fields.template declare<Mat<D>>(spec("NextCp"), Mat<D>::Identity())),
          committedZZ_(fields.template declare<double>(scalar("CommittedZZ"), 1.0)),
          committedAlpha_(fields.template declare<double>(scalar("CommittedAlpha"), nan())),
          committedPressure_(fields.template declare<double>(scalar("CommittedPressure"), nan())),
          waveModulus_(fields.template declare<double>(scalar("WaveModulus"), 0.0)),
          deltaGamma_(fields.template declare<double>(scalar("DeltaGamma"), 0.0)),
          nextAlpha_(fields.template declare<double>(scalar("NextAlpha"), 0.0)),
          nextZZ_(fields.template declare<double>(scalar("NextZZ"), 1.0)),
          dissipation_(fields.template declare<double>(scalar("Dissipation"), 0.0)),
          nextPressure_(fields.template declare<double>(scalar("NextPressure"), noFlowPressure))
    {
    }

    // Called by the one thread that handles particle a.
    void store(std::size_t a, const Mat<D>& F, const PlasticState<D>& committed, const Entry& e)
    {
        if (a >= F_.size())
        {
            return; // a material built alone (tests) evaluating points it was not sized for
        }
        F_[a] = F;
        committedCp_[a] = committed.inversePlastic;
        committedZZ_[a] = committed.inversePlasticZZ;
        committedAlpha_[a] = committed.alpha;
        committedPressure_[a] = committed.flowPressure;
        waveModulus_[a] = e.waveModulus;
        deltaGamma_[a] = e.flow.deltaGamma;
        nextAlpha_[a] = e.flow.alpha;
        dissipation_[a] = e.flow.dissipation;
        nextPressure_[a] = e.flow.pressure;
        nextCp_[a] = e.next.inversePlastic;
        nextZZ_[a] = e.next.inversePlasticZZ;
    }

    // The entry of particle a if it was computed from exactly F and `committed`.
    bool find(std::size_t a, const Mat<D>& F, const PlasticState<D>& committed, Entry& e) const
    {
        if (a >= F_.size() || !sameBits(F_[a], F) ||
            !sameBits(committedCp_[a], committed.inversePlastic) ||
            !sameBits(committedZZ_[a], committed.inversePlasticZZ) ||
            !sameBits(committedAlpha_[a], committed.alpha) ||
            !sameBits(committedPressure_[a], committed.flowPressure))
        {
            return false;
        }
        e.waveModulus = waveModulus_[a];
        e.flow = {deltaGamma_[a], nextAlpha_[a], dissipation_[a], nextPressure_[a]};
        e.next.inversePlastic = nextCp_[a];
        e.next.inversePlasticZZ = nextZZ_[a];
        e.next.flowPressure = nextPressure_[a];
        e.next.alpha = nextAlpha_[a];
        return true;
    }

private:
    static double nan() { return std::numeric_limits<double>::quiet_NaN(); }
    // Bitwise, not ==: −0 and 0 are different inputs to the return. No entry yet: F and α are
    // NaN, which no committed state has.
    template <class T>
    static bool sameBits(const T& a, const T& b)
    {
        return std::memcmp(&a, &b, sizeof(T)) == 0;
    }
    static FieldSpec spec(const char* name)
    {
        return FieldSpec::tensor(std::string("returnMemo") + name,
                                 "scratch: the last return map of the particle (issue 30)");
    }
    static FieldSpec scalar(const char* name)
    {
        return FieldSpec::scalar(std::string("returnMemo") + name,
                                 "scratch: the last return map of the particle (issue 30)");
    }

    std::vector<Mat<D>>& F_;
    std::vector<Mat<D>>& committedCp_;
    std::vector<Mat<D>>& nextCp_;
    std::vector<double>& committedZZ_;
    std::vector<double>& committedAlpha_;
    std::vector<double>& committedPressure_;
    std::vector<double>& waveModulus_;
    std::vector<double>& deltaGamma_;
    std::vector<double>& nextAlpha_;
    std::vector<double>& nextZZ_;
    std::vector<double>& dissipation_;
    std::vector<double>& nextPressure_;
};

} // namespace sph
