#pragma once
// The frames of total-Lagrangian samples that carry their elastic state (gradF `plasticSamples
// elasticState` in total-Lagrangian form, docs/theory/gradF-plastic.md §G25). Each particle a
// keeps F°_a, G°_a and x°_a of the last commit (at t = 0: I, 0 and X_a); its stress sample of
// pair a–b is the step's increment expanded in the frame's configuration (G25.1):
//
//     F_b(a) = F_a M_ab + G_a[z_ab],   z_ab = F°_a⁻¹ (x°_b − x°_a),   M_ab = I − F°_a⁻¹ G°_a[z_ab],
//
// so that F_b(a) = F°_a at the frame's own positions and the samples' differences live in their
// states. The frames are particle fields (restart data; a ghost gets its owner's when it is
// gathered, and z_ab reads the neighbour's x°). A force evaluation hands over its F_a and G_a
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
        G_.assign(n, Tensor3<D>::zero());
        x_.assign(n, Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN()));
        fields.bind(FieldSpec::tensor("sampleFrameF", "F° of gradF's total-Lagrangian elasticState "
                                                      "samples: F at the last commit (§G25)")
                        .restart(),
                    F_, Mat<D>::Identity());
        fields.bind(FieldSpec::thirdOrderTensor("sampleFrameG", "G° = dF°/dX at the last commit "
                                                                "(§G25), G_ijk")
                        .restart(),
                    G_);
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
                G_[a] = Tensor3<D>::zero();
            }
        }
    }

    // z_ab and M_ab of particle a's samples along its neighbour list (a itself first: z = 0,
    // M = I).
    void offsets(std::size_t a, const NeighbourList& list, Vec<D>* z, Mat<D>* M) const
    {
        const Mat<D> inverse = F_[a].inverse();
        const std::size_t first = list.begin(a);
        z[0].setZero();
        M[0].setIdentity();
        for (std::size_t j = 1; j < list.count(a); ++j)
        {
            const std::size_t b = list.indices[first + j];
            z[j] = inverse * (x_[b] - x_[a]);
            M[j] = Mat<D>::Identity() - inverse * G_[a].contract(z[j]);
        }
    }
    // F_b(a) = F M_ab + G[z_ab] of count samples (G25.1).
    static void samples(const Mat<D>& F, const Tensor3<D>& G, const Vec<D>* z, const Mat<D>* M,
                        std::size_t count, Mat<D>* out)
    {
        for (std::size_t j = 0; j < count; ++j)
        {
            out[j] = F * M[j] + G.contract(z[j]);
        }
    }

    // What a force evaluation found (its F_a, G_a and positions): where a commit moves the
    // frames. The operator probe's evaluations are set aside and the last level's restored.
    void evaluated(std::size_t a, const Mat<D>& F, const Tensor3<D>& G)
    {
        evaluated_.F[a] = F;
        evaluated_.G[a] = G;
    }
    void evaluatedAt(const std::vector<Vec<D>>& x)
    {
        evaluated_.x = x;
        evaluated_.F.resize(x.size());
        evaluated_.G.resize(x.size());
    }
    void setAside() { std::swap(evaluated_, aside_); }
    void restore() { std::swap(evaluated_, aside_); }
    const Mat<D>& evaluatedF(std::size_t a) const { return evaluated_.F[a]; }
    const Tensor3<D>& evaluatedG(std::size_t a) const { return evaluated_.G[a]; }
    bool hasEvaluation(std::size_t n) const { return evaluated_.x.size() == n; }

    // The frames moved to the last evaluation (after its states were rebased there).
    void move()
    {
        F_ = evaluated_.F;
        G_ = evaluated_.G;
        x_ = evaluated_.x;
    }

private:
    struct Evaluation
    {
        std::vector<Mat<D>> F;
        std::vector<Tensor3<D>> G;
        std::vector<Vec<D>> x;
    };
    bool active_ = false;
    std::vector<Mat<D>> F_;
    std::vector<Tensor3<D>> G_;
    std::vector<Vec<D>> x_;
    Evaluation evaluated_;
    Evaluation aside_;
};

} // namespace sph
