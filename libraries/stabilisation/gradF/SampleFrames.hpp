#pragma once
// The frames of total-Lagrangian samples that carry their elastic state (gradF `plasticSamples
// elasticState` in total-Lagrangian form, docs/theory/gradF-plastic.md §G25-§G26). Each particle
// a keeps F°_a and x°_a of the last commit (at t = 0: I and X_a); its stress sample of pair a–b is
// the step's increment expanded in the frame's configuration (G26.1):
//
//     F_b(a) = F_a + H°_a[y°_ab] F°_a,   y°_ab = x°_b − x°_a,
//
// H°_a the increment's gradient fitted in the frame's configuration (GradFSampleFrames.cpp), so
// that F_b(a) = F°_a at the frame's own positions and the samples' differences live in their
// states. The frames are particle fields (restart data; a ghost gets its owner's when it is
// gathered, and y°_ab reads the neighbour's x°). A force evaluation hands over its F_a and H°_a
// (evaluated()); the commit rebases the states to them and moves the frames there (move()).

#include "particles/NeighbourList.hpp"
#include "particles/ParticleFields.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace sph
{

template <int D>
class SampleFrames
{
public:
    void declare(ParticleFields<D>& fields)
    {
        const std::size_t n = fields.size();
        F_.assign(n, Mat<D>::Identity());
        x_.assign(n, Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN()));
        fields.bind(FieldSpec::tensor("sampleFrameF", "F° of gradF's total-Lagrangian elasticState "
                                                      "samples: F at the last commit (§G25)")
                        .restart(),
                    F_, Mat<D>::Identity());
        fields.bind(FieldSpec::vector("sampleFramePosition", "x° = x at the last commit (§G25) "
                                                             "[m]; NaN: not framed yet")
                        .restart(),
                    x_, Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN()));
        active_ = true;
    }
    bool active() const { return active_; }

    // The particles not framed yet (a new run, or particles added) start at the reference: the
    // frame of t = 0, where the samples are the paper's.
    void start(const std::vector<Vec<D>>& X)
    {
        for (std::size_t a = 0; a < x_.size(); ++a)
        {
            if (std::isnan(x_[a][0]))
            {
                x_[a] = X[a];
                F_[a].setIdentity();
            }
        }
    }

    const Mat<D>& frameF(std::size_t a) const { return F_[a]; }
    const Vec<D>& position(std::size_t a) const { return x_[a]; }

    // y°_ab = x°_b − x°_a along particle a's neighbour list (a itself first: 0).
    void offsets(std::size_t a, const NeighbourList& list, Vec<D>* y) const
    {
        const std::size_t first = list.begin(a);
        y[0].setZero();
        for (std::size_t j = 1; j < list.count(a); ++j)
        {
            y[j] = x_[list.indices[first + j]] - x_[a];
        }
    }
    // F_b(a) = F + H°[y°_ab] F°_a of particle a's count samples (G26.1).
    void samples(std::size_t a, const Mat<D>& F, const Tensor3<D>& H, const Vec<D>* y,
                 std::size_t count, Mat<D>* out) const
    {
        for (std::size_t j = 0; j < count; ++j)
        {
            out[j] = F + H.contract(y[j]) * F_[a];
        }
    }

    // What a force evaluation found (its F_a, H°_a and positions): where a commit moves the
    // frames. The operator probe's evaluations are set aside and the last level's restored.
    void evaluated(std::size_t a, const Mat<D>& F, const Tensor3<D>& H)
    {
        evaluated_.F[a] = F;
        evaluated_.H[a] = H;
    }
    void evaluatedAt(const std::vector<Vec<D>>& x)
    {
        evaluated_.x = x;
        evaluated_.F.resize(x.size());
        evaluated_.H.resize(x.size());
    }
    void setAside() { std::swap(evaluated_, aside_); }
    void restore() { std::swap(evaluated_, aside_); }
    const Mat<D>& evaluatedF(std::size_t a) const { return evaluated_.F[a]; }
    const Tensor3<D>& evaluatedH(std::size_t a) const { return evaluated_.H[a]; }
    bool hasEvaluation(std::size_t n) const { return evaluated_.x.size() == n; }

    // The frames moved to the last evaluation (after its states were rebased there).
    void move()
    {
        F_ = evaluated_.F;
        x_ = evaluated_.x;
    }

private:
    struct Evaluation
    {
        std::vector<Mat<D>> F;
        std::vector<Tensor3<D>> H; // H°_a, the increment's gradient in the frame (§G26)
        std::vector<Vec<D>> x;
    };
    bool active_ = false;
    std::vector<Mat<D>> F_;
    std::vector<Vec<D>> x_;
    Evaluation evaluated_;
    Evaluation aside_;
};

} // namespace sph
