// Header-only C++17 RAII wrapper over the orthoslip C API: owning handles for material,
// contact and solution, and an exception carrying the status and the library's message.
#ifndef ORTHOSLIP_HPP
#define ORTHOSLIP_HPP

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "orthoslip.h"

namespace orthoslip {

/// A failed call: the status and this thread's last error message at the time of failure.
class error : public std::runtime_error {
  public:
    error(orthoslip_status status, const std::string &message)
        : std::runtime_error(std::string(orthoslip_status_string(status)) + ": " + message),
          status_(status) {}
    orthoslip_status status() const noexcept { return status_; }

  private:
    orthoslip_status status_;
};

/// This thread's last error message.
inline std::string last_error_message() {
    std::string msg(orthoslip_last_error_message(nullptr, 0), '\0');
    if (!msg.empty()) {
        orthoslip_last_error_message(msg.data(), msg.size() + 1);
    }
    return msg;
}

/// Throws `error` unless `status` is ORTHOSLIP_OK.
inline void check(orthoslip_status status) {
    if (status != ORTHOSLIP_OK) {
        throw error(status, last_error_message());
    }
}

namespace detail {
template <class T, void (*Free)(T *)> struct deleter {
    void operator()(T *p) const noexcept { Free(p); }
};
template <class T, void (*Free)(T *)> using handle = std::unique_ptr<T, deleter<T, Free>>;
} // namespace detail

struct effective_constants {
    double e, nu, delta, kappa;
};
struct green_constants {
    double a, b, c;
};
struct tractions {
    std::vector<double> p, q;
};
/// Stresses per P/a inside the solid (tension positive).
struct stresses {
    std::vector<double> sxx, syy, sxy;
};
/// The punch-edge singularity p ~ k (1 - |x|)^(-g).
struct edge_intensity {
    double k, g;
};

class solution {
  public:
    double stick_half_width() const { return get(orthoslip_solution_stick_half_width); }
    /// 1 - c with full relative accuracy.
    double slip_width() const { return get(orthoslip_solution_slip_width); }
    double error_estimate() const { return get(orthoslip_solution_error_estimate); }
    /// Estimate of int (|dp| + |dq|) dx over the punch, in units of the load P.
    double traction_error_estimate() const {
        return get(orthoslip_solution_traction_error_estimate);
    }
    orthoslip_method method() const {
        orthoslip_method used;
        check(orthoslip_solution_method(h_.get(), &used));
        return used;
    }
    /// p(x), q(x) at `x` (units of the punch half-width).
    tractions at(const std::vector<double> &x) const {
        tractions t{std::vector<double>(x.size()), std::vector<double>(x.size())};
        check(orthoslip_solution_tractions(h_.get(), x.data(), x.size(), t.p.data(), t.q.data()));
        return t;
    }
    /// Stresses at the points (x[i], y[i]), units of a, y <= 0 (the solid is y < 0).
    orthoslip::stresses stresses(const std::vector<double> &x, const std::vector<double> &y) const {
        if (x.size() != y.size()) {
            throw std::invalid_argument("orthoslip::solution::stresses: x and y differ in size");
        }
        const auto n = x.size();
        orthoslip::stresses st{std::vector<double>(n), std::vector<double>(n),
                               std::vector<double>(n)};
        if (n == 0) {
            return st; // empty vectors may hold no pointer at all
        }
        check(orthoslip_solution_stresses(h_.get(), x.data(), y.data(), n, st.sxx.data(),
                                          st.syy.data(), st.sxy.data()));
        return st;
    }
    orthoslip::edge_intensity edge_intensity() const {
        orthoslip::edge_intensity e{};
        check(orthoslip_solution_edge_intensity(h_.get(), &e.k, &e.g));
        return e;
    }
    /// Tangential surface displacement relative to the punch, per P/E, at `x`.
    std::vector<double> slip(const std::vector<double> &x) const {
        std::vector<double> u(x.size());
        if (x.empty()) {
            return u;
        }
        check(orthoslip_solution_slip(h_.get(), x.data(), x.size(), u.data()));
        return u;
    }
    const orthoslip_solution *get() const noexcept { return h_.get(); }

  private:
    friend class contact;
    explicit solution(orthoslip_solution *raw) : h_(raw) {}
    double get(orthoslip_status (*f)(const orthoslip_solution *, double *)) const {
        double v;
        check(f(h_.get(), &v));
        return v;
    }
    detail::handle<orthoslip_solution, orthoslip_solution_free> h_;
};

class material {
  public:
    static material plane_stress(double e11, double e22, double g12, double nu12) {
        orthoslip_material *raw = nullptr;
        check(orthoslip_material_new_plane_stress(e11, e22, g12, nu12, &raw));
        return material(raw);
    }
    static material plane_strain(double e11, double e22, double e33, double g12, double nu12,
                                 double nu13, double nu23) {
        orthoslip_material *raw = nullptr;
        check(orthoslip_material_new_plane_strain(e11, e22, e33, g12, nu12, nu13, nu23, &raw));
        return material(raw);
    }
    static material effective(double e, double nu, double delta, double kappa) {
        orthoslip_material *raw = nullptr;
        check(orthoslip_material_new_effective(e, nu, delta, kappa, &raw));
        return material(raw);
    }
    effective_constants effective() const {
        effective_constants k{};
        check(orthoslip_material_effective(h_.get(), &k.e, &k.nu, &k.delta, &k.kappa));
        return k;
    }
    green_constants green() const {
        green_constants g{};
        check(orthoslip_material_green(h_.get(), &g.a, &g.b, &g.c));
        return g;
    }
    const orthoslip_material *get() const noexcept { return h_.get(); }

  private:
    explicit material(orthoslip_material *raw) : h_(raw) {}
    detail::handle<orthoslip_material, orthoslip_material_free> h_;
};

class contact {
  public:
    /// Copies the material; `m` may be destroyed afterwards.
    explicit contact(const material &m) {
        orthoslip_contact *raw = nullptr;
        check(orthoslip_contact_new(m.get(), &raw));
        h_.reset(raw);
    }
    contact &friction(double mu) {
        check(orthoslip_contact_set_friction(h_.get(), mu));
        return *this;
    }
    contact &method(orthoslip_method m) {
        check(orthoslip_contact_set_method(h_.get(), m));
        return *this;
    }
    contact &tolerance(double tol) {
        check(orthoslip_contact_set_tolerance(h_.get(), tol));
        return *this;
    }
    /// INFINITY: tractions not needed (default: follows `tolerance`).
    contact &traction_tolerance(double tol) {
        check(orthoslip_contact_set_traction_tolerance(h_.get(), tol));
        return *this;
    }
    solution solve() const {
        orthoslip_solution *raw = nullptr;
        check(orthoslip_contact_solve(h_.get(), &raw));
        return solution(raw);
    }
    const orthoslip_contact *get() const noexcept { return h_.get(); }

  private:
    detail::handle<orthoslip_contact, orthoslip_contact_free> h_;
};

} // namespace orthoslip

#endif
