#pragma once
// Smoothing kernels W(r, h) = (sigma_d / h^d) w(q), q = r/h (spec §1), runtime-selectable:
//
//   kernel { type cubicSpline; hOverDx 1.5; }
//
// Keys common to every kernel:
//   hOverDx | smoothing length h relative to the particle spacing | 1.5
//
// A kernel is dimension-independent code: the dimension only picks the normalisation.
// evaluate() works on a batch (one particle's neighbours) so the hot loops pay one virtual
// call per particle, not per pair.

#include "core/Format.hpp"
#include "core/Registry.hpp"

#include <cmath>
#include <string>

namespace sph
{

class Kernel : public RegisteredModel
{
public:
    static constexpr const char* family = "kernel";
    static constexpr int dimension = 0;
    struct Args
    {
        int dimension = 1;    // of the case: 1, 2 or 3
        double spacing = 1.0; // particle spacing Δx; h = hOverDx · Δx
    };

    virtual ~Kernel() = default;

    double h() const { return h_; }
    double hOverDx() const { return hOverDx_; }
    int spaceDimension() const { return dimension_; }
    // Support radius in units of h (2 for the cubic spline) and in length.
    double supportFactor() const { return supportFactor_; }
    double supportRadius() const { return supportFactor_ * h_; }

    virtual double W(double r) const = 0;
    virtual double dWdr(double r) const = 0;
    // W and dW/dr for n distances.
    virtual void evaluate(const double* r, std::size_t n, double* W, double* dWdr) const = 0;
    // The registered name ("cubicSpline").
    const std::string& name() const { return typeName(); }

    static Schema commonSchema()
    {
        return Schema().add(Key::real("hOverDx", "smoothing length h relative to the particle "
                                                 "spacing")
                                .range(0.5, 4.0, false, true)
                                .defaultValue("1.5"));
    }

protected:
    Kernel(const Params& params, const Args& args, double supportFactor)
        : dimension_(args.dimension), hOverDx_(params.real("hOverDx")),
          h_(hOverDx_ * args.spacing), supportFactor_(supportFactor)
    {
    }
    // "cubicSpline(hOverDx=1.5, h=0.0051 m)"
    std::vector<std::string> summaryExtras() const override
    {
        return {"h=" + formatNumber(h_) + " m"};
    }

private:
    int dimension_;
    double hOverDx_;
    double h_;
    double supportFactor_;
};

// Implements Kernel for a shape
//   struct Shape { static constexpr double support; static double sigma(int dim);
//                  static double w(double q, int dim); static double dwdq(double q, int dim); }
// with the normalisation and h-scaling done once here.
template <class Shape>
class KernelModel : public Kernel
{
public:
    KernelModel(const Params& params, const Args& args)
        : Kernel(params, args, Shape::support), scaleW_(Shape::sigma(args.dimension) /
                                                       std::pow(h(), args.dimension)),
          scaleGrad_(scaleW_ / h()), invH_(1.0 / h())
    {
    }

    double W(double r) const final { return scaleW_ * Shape::w(r * invH_, spaceDimension()); }
    double dWdr(double r) const final
    {
        return scaleGrad_ * Shape::dwdq(r * invH_, spaceDimension());
    }
    void evaluate(const double* r, std::size_t n, double* W, double* dWdr) const final
    {
        const int dim = spaceDimension();
        for (std::size_t i = 0; i < n; ++i)
        {
            const double q = r[i] * invH_;
            W[i] = scaleW_ * Shape::w(q, dim);
            dWdr[i] = scaleGrad_ * Shape::dwdq(q, dim);
        }
    }

private:
    double scaleW_;
    double scaleGrad_;
    double invH_;
};

} // namespace sph
