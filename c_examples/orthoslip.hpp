// Header-only C++17 RAII wrapper over the orthoslip C API: owning handles for material,
// contact and solution, for load paths (history) and fretting runs (cycles), and an
// exception carrying the status and the library's message.
#ifndef ORTHOSLIP_HPP
#define ORTHOSLIP_HPP

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
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
/// A stick set [c1, c2] and the estimate of its ends' error.
struct stick_zone {
    double c1, c2, error;
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
    /// The stick set [c1, c2] ([-c, c] for a normal-load solution) and error_estimate().
    orthoslip::stick_zone stick_zone() const {
        orthoslip::stick_zone z{};
        check(orthoslip_solution_stick_zone(h_.get(), &z.c1, &z.c2));
        z.error = error_estimate();
        return z;
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
    friend class history;
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

/// Options of a load path or a fretting run (defaults: LCP history, 100 panels per
/// half-width, 10 load steps per quarter cycle, repeat tolerance 1e-8).
class cycle_options {
  public:
    cycle_options() {
        orthoslip_cycle_options *raw = nullptr;
        check(orthoslip_cycle_options_new(&raw));
        h_.reset(raw);
    }
    cycle_options &method(orthoslip_cycle_method m) {
        check(orthoslip_cycle_options_set_method(h_.get(), m));
        return *this;
    }
    cycle_options &panels(std::size_t n) {
        check(orthoslip_cycle_options_set_panels(h_.get(), n));
        return *this;
    }
    cycle_options &steps(std::size_t n) {
        check(orthoslip_cycle_options_set_steps(h_.get(), n));
        return *this;
    }
    cycle_options &repeat_tolerance(double tol) {
        check(orthoslip_cycle_options_set_repeat_tolerance(h_.get(), tol));
        return *this;
    }
    const orthoslip_cycle_options *get() const noexcept { return h_.get(); }

  private:
    detail::handle<orthoslip_cycle_options, orthoslip_cycle_options_free> h_;
};

/// A value with its error estimate.
struct estimate {
    double value, error;
};
/// p, q and the zone (0 stick, +1 slip in +x, -1 slip in -x) at points.
struct path_tractions {
    std::vector<double> p, q;
    std::vector<int> zone;
};
/// The Q-displacement loop of a cycle: Q/P and u (per P/E).
struct cycle_loop {
    std::vector<double> q_over_p, u;
};

/// A load path: the normal load, then Q moved monotonically by `load` (per P/E, P^2/E).
class history {
  public:
    /// Q moves monotonically to q_over_p * P; on failure the path is unchanged.
    void load(double q_over_p) { check(orthoslip_history_load(h_.get(), q_over_p)); }
    orthoslip::stick_zone stick_zone() const {
        orthoslip::stick_zone z{};
        check(orthoslip_history_stick_zone(h_.get(), &z.c1, &z.c2, &z.error));
        return z;
    }
    path_tractions at(const std::vector<double> &x) const {
        path_tractions t{std::vector<double>(x.size()), std::vector<double>(x.size()),
                         std::vector<int>(x.size())};
        if (!x.empty()) {
            check(orthoslip_history_tractions(h_.get(), x.data(), x.size(), t.p.data(),
                                              t.q.data(), t.zone.data()));
        }
        return t;
    }
    estimate dissipated_energy() const {
        estimate e{};
        check(orthoslip_history_dissipated_energy(h_.get(), &e.value, &e.error));
        return e;
    }
    /// The current state as a solution (no single c, edge intensity or slip: those getters
    /// throw ORTHOSLIP_ERROR_INVALID_ARGUMENT; stick_zone() gives [c1, c2]).
    orthoslip::solution solution() const {
        orthoslip_solution *raw = nullptr;
        check(orthoslip_history_solution(h_.get(), &raw));
        return orthoslip::solution(raw);
    }
    const orthoslip_history *get() const noexcept { return h_.get(); }

  private:
    friend class contact;
    explicit history(orthoslip_history *raw) : h_(raw) {}
    detail::handle<orthoslip_history, orthoslip_history_free> h_;
};

/// A fretting run: cycles Q* -> -Q* -> Q* after the first loading (cycle 0 is the first).
class cycles {
  public:
    std::size_t count() const {
        std::size_t n = 0;
        int steady = 0;
        check(orthoslip_cycles_count(h_.get(), &n, &steady));
        return n;
    }
    orthoslip_cycle_state state() const {
        orthoslip_cycle_state s{};
        check(orthoslip_cycles_state(h_.get(), &s));
        return s;
    }
    /// Energy dissipated in a cycle (P^2/E) and its error estimate.
    estimate dissipated_energy(std::size_t cycle) const {
        estimate e{};
        check(orthoslip_cycles_dissipated_energy(h_.get(), cycle, &e.value));
        check(orthoslip_cycles_dissipated_energy_error(h_.get(), cycle, &e.error));
        return e;
    }
    /// Slip amplitude (per P/E) at x in [-1, 1].
    std::vector<double> slip_amplitude(std::size_t cycle, const std::vector<double> &x) const {
        std::vector<double> a(x.size());
        if (!x.empty()) {
            check(orthoslip_cycles_slip_amplitude(h_.get(), cycle, x.data(), x.size(), a.data()));
        }
        return a;
    }
    /// Ruiz's F1 and F2 at x in [-1, 1].
    std::pair<std::vector<double>, std::vector<double>> ruiz(std::size_t cycle,
                                                             const std::vector<double> &x) const {
        std::vector<double> f1(x.size()), f2(x.size());
        if (!x.empty()) {
            check(orthoslip_cycles_ruiz(h_.get(), cycle, x.data(), x.size(), f1.data(),
                                        f2.data()));
        }
        return {f1, f2};
    }
    cycle_loop loop(std::size_t cycle) const {
        std::size_t n = 0;
        check(orthoslip_cycles_loop_length(h_.get(), cycle, &n));
        cycle_loop l{std::vector<double>(n), std::vector<double>(n)};
        check(orthoslip_cycles_loop(h_.get(), cycle, n, l.q_over_p.data(), l.u.data()));
        return l;
    }
    /// The stick sets at -Q* (first) and +Q* (second); the error estimate in both.
    std::pair<orthoslip::stick_zone, orthoslip::stick_zone> stick_zones(std::size_t cycle) const {
        orthoslip::stick_zone m{}, p{};
        check(orthoslip_cycles_stick_zones(h_.get(), cycle, &m.c1, &m.c2, &p.c1, &p.c2,
                                           &m.error));
        p.error = m.error;
        return {m, p};
    }
    const orthoslip_cycles *get() const noexcept { return h_.get(); }

  private:
    friend class contact;
    explicit cycles(orthoslip_cycles *raw) : h_(raw) {}
    detail::handle<orthoslip_cycles, orthoslip_cycles_free> h_;
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
    /// Fretting: Q cycled +q_amp P -> -q_amp P -> +q_amp P after the normal load.
    orthoslip::cycles solve_cycles(double q_amp_over_p, std::size_t max_cycles,
                                   const cycle_options &o = cycle_options()) const {
        orthoslip_cycles *raw = nullptr;
        check(orthoslip_contact_solve_cycles_with_options(h_.get(), o.get(), q_amp_over_p,
                                                          max_cycles, &raw));
        return orthoslip::cycles(raw);
    }
    /// A load path from the normal-load state.
    orthoslip::history history(const cycle_options &o = cycle_options()) const {
        orthoslip_history *raw = nullptr;
        check(orthoslip_history_new_with_options(h_.get(), o.get(), &raw));
        return orthoslip::history(raw);
    }
    const orthoslip_contact *get() const noexcept { return h_.get(); }

  private:
    detail::handle<orthoslip_contact, orthoslip_contact_free> h_;
};

} // namespace orthoslip

#endif
