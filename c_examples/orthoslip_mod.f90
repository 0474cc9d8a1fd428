! Fortran 2008 bindings (iso_c_binding) for the orthoslip C API (include/orthoslip.h).
! Handles are type(c_ptr); a `T **out` argument is type(c_ptr), intent(out); enums are
! integer(c_int). Helpers turn the library's C strings into Fortran strings.
module orthoslip_mod
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_char, &
       c_null_ptr, c_null_char, c_loc, c_f_pointer, c_associated
  implicit none
  private

  ! orthoslip_status
  integer(c_int), parameter, public :: ORTHOSLIP_OK = 0
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_NULL_POINTER = 1
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_INVALID_ARGUMENT = 2
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL = 3
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_NO_CONVERGENCE = 4
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_TOLERANCE_NOT_MET = 5
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_INTERNAL = 6
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_PANIC = 7
  integer(c_int), parameter, public :: ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION = 8
  ! orthoslip_method
  integer(c_int), parameter, public :: ORTHOSLIP_METHOD_AUTO = 0
  integer(c_int), parameter, public :: ORTHOSLIP_METHOD_GOODMAN = 1
  integer(c_int), parameter, public :: ORTHOSLIP_METHOD_SPENCE = 2
  integer(c_int), parameter, public :: ORTHOSLIP_METHOD_COUPLED = 3
  integer(c_int), parameter, public :: ORTHOSLIP_METHOD_LCP = 4

  ! orthoslip_cycle_method
  integer(c_int), parameter, public :: ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY = 0
  integer(c_int), parameter, public :: ORTHOSLIP_CYCLE_METHOD_EXACT = 1
  ! orthoslip_cycle_state
  integer(c_int), parameter, public :: ORTHOSLIP_CYCLE_SHAKEDOWN = 0
  integer(c_int), parameter, public :: ORTHOSLIP_CYCLE_STEADY_SLIP = 1
  integer(c_int), parameter, public :: ORTHOSLIP_CYCLE_LIMIT_REACHED = 2

  public :: orthoslip_material_new_plane_stress, orthoslip_material_new_plane_strain, &
       orthoslip_material_new_effective, orthoslip_material_free, &
       orthoslip_material_effective, orthoslip_material_green, &
       orthoslip_contact_new, orthoslip_contact_free, orthoslip_contact_set_friction, &
       orthoslip_contact_set_method, orthoslip_contact_set_tolerance, orthoslip_contact_solve, &
       orthoslip_solution_free, orthoslip_solution_stick_half_width, &
       orthoslip_solution_slip_width, orthoslip_solution_tractions, orthoslip_solution_method, &
       orthoslip_solution_error_estimate, orthoslip_last_error_message, &
       orthoslip_status_string, orthoslip_version, orthoslip_solution_stresses, &
       orthoslip_solution_edge_intensity, orthoslip_solution_slip, &
       orthoslip_solution_traction_error_estimate, orthoslip_contact_set_traction_tolerance
  public :: orthoslip_cycle_options_new, orthoslip_cycle_options_free, &
       orthoslip_cycle_options_set_method, orthoslip_cycle_options_set_panels, &
       orthoslip_cycle_options_set_steps, orthoslip_cycle_options_set_repeat_tolerance, &
       orthoslip_solution_stick_zone, orthoslip_history_new, &
       orthoslip_history_new_with_options, orthoslip_history_free, &
       orthoslip_history_load, orthoslip_history_state, &
       orthoslip_history_stick_zone, orthoslip_history_tractions, &
       orthoslip_history_dissipated_energy, orthoslip_history_traction_error_estimate, &
       orthoslip_contact_solve_cycles, orthoslip_contact_solve_cycles_with_options, &
       orthoslip_cycles_free, orthoslip_cycles_count, &
       orthoslip_cycles_method, orthoslip_cycles_state, &
       orthoslip_cycles_dissipated_energy, orthoslip_cycles_dissipated_energy_error, &
       orthoslip_cycles_first_loading_energy, orthoslip_cycles_slip_amplitude, &
       orthoslip_cycles_slip_amplitude_error, orthoslip_cycles_ruiz, &
       orthoslip_cycles_stress_peaks, orthoslip_cycles_ruiz_peaks, &
       orthoslip_cycles_stick_zones, orthoslip_cycles_loop_length, &
       orthoslip_cycles_loop, orthoslip_cycles_loop_error, orthoslip_cycles_energy_balance, &
       orthoslip_cycles_step, orthoslip_cycles_step_tractions, orthoslip_history_solution
  public :: last_error_message, status_name, version

  interface
    function orthoslip_material_new_plane_stress(e11, e22, g12, nu12, out) &
         bind(c, name="orthoslip_material_new_plane_stress") result(status)
      import :: c_int, c_double, c_ptr
      real(c_double), value :: e11, e22, g12, nu12
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    function orthoslip_material_new_plane_strain(e11, e22, e33, g12, nu12, nu13, nu23, out) &
         bind(c, name="orthoslip_material_new_plane_strain") result(status)
      import :: c_int, c_double, c_ptr
      real(c_double), value :: e11, e22, e33, g12, nu12, nu13, nu23
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    function orthoslip_material_new_effective(e, nu, delta, kappa, out) &
         bind(c, name="orthoslip_material_new_effective") result(status)
      import :: c_int, c_double, c_ptr
      real(c_double), value :: e, nu, delta, kappa
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    subroutine orthoslip_material_free(m) bind(c, name="orthoslip_material_free")
      import :: c_ptr
      type(c_ptr), value :: m
    end subroutine

    function orthoslip_material_effective(m, e, nu, delta, kappa) &
         bind(c, name="orthoslip_material_effective") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: m
      real(c_double), intent(out) :: e, nu, delta, kappa
      integer(c_int) :: status
    end function

    function orthoslip_material_green(m, a, b, c) bind(c, name="orthoslip_material_green") &
         result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: m
      real(c_double), intent(out) :: a, b, c
      integer(c_int) :: status
    end function

    function orthoslip_contact_new(m, out) bind(c, name="orthoslip_contact_new") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: m
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    subroutine orthoslip_contact_free(k) bind(c, name="orthoslip_contact_free")
      import :: c_ptr
      type(c_ptr), value :: k
    end subroutine

    function orthoslip_contact_set_friction(k, mu) bind(c, name="orthoslip_contact_set_friction") &
         result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: k
      real(c_double), value :: mu
      integer(c_int) :: status
    end function

    function orthoslip_contact_set_method(k, method) bind(c, name="orthoslip_contact_set_method") &
         result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: k
      integer(c_int), value :: method
      integer(c_int) :: status
    end function

    function orthoslip_contact_set_tolerance(k, tol) &
         bind(c, name="orthoslip_contact_set_tolerance") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: k
      real(c_double), value :: tol
      integer(c_int) :: status
    end function

    function orthoslip_contact_solve(k, out) bind(c, name="orthoslip_contact_solve") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: k
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    subroutine orthoslip_solution_free(s) bind(c, name="orthoslip_solution_free")
      import :: c_ptr
      type(c_ptr), value :: s
    end subroutine

    function orthoslip_solution_stick_half_width(s, c) &
         bind(c, name="orthoslip_solution_stick_half_width") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(out) :: c
      integer(c_int) :: status
    end function

    function orthoslip_solution_slip_width(s, one_minus_c) &
         bind(c, name="orthoslip_solution_slip_width") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(out) :: one_minus_c
      integer(c_int) :: status
    end function

    function orthoslip_solution_tractions(s, x, n, p, q) &
         bind(c, name="orthoslip_solution_tractions") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(in) :: x(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: p(*), q(*)
      integer(c_int) :: status
    end function

    function orthoslip_solution_method(s, used) bind(c, name="orthoslip_solution_method") &
         result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: s
      integer(c_int), intent(out) :: used
      integer(c_int) :: status
    end function

    function orthoslip_solution_error_estimate(s, c_error) &
         bind(c, name="orthoslip_solution_error_estimate") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(out) :: c_error
      integer(c_int) :: status
    end function

    function orthoslip_solution_traction_error_estimate(s, err) &
         bind(c, name="orthoslip_solution_traction_error_estimate") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    ! tol = ieee_value(tol, ieee_positive_inf): tractions not needed.
    function orthoslip_contact_set_traction_tolerance(k, tol) &
         bind(c, name="orthoslip_contact_set_traction_tolerance") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: k
      real(c_double), value :: tol
      integer(c_int) :: status
    end function

    ! buf may be c_null_ptr when len == 0; returns the message length without the NUL.
    function orthoslip_last_error_message(buf, len) bind(c, name="orthoslip_last_error_message") &
         result(full_len)
      import :: c_size_t, c_ptr
      type(c_ptr), value :: buf
      integer(c_size_t), value :: len
      integer(c_size_t) :: full_len
    end function

    function orthoslip_status_string(status) bind(c, name="orthoslip_status_string") result(str)
      import :: c_int, c_ptr
      integer(c_int), value :: status
      type(c_ptr) :: str
    end function

    function orthoslip_version() bind(c, name="orthoslip_version") result(str)
      import :: c_ptr
      type(c_ptr) :: str
    end function

    ! Stresses per P/a at (x(i), y(i)), units of a, y <= 0 (the solid is y < 0).
    function orthoslip_solution_stresses(s, x, y, n, sxx, syy, sxy) &
         bind(c, name="orthoslip_solution_stresses") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(in) :: x(*), y(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: sxx(*), syy(*), sxy(*)
      integer(c_int) :: status
    end function

    ! p ~ k (1 - |x|)^(-g) at the punch edges.
    function orthoslip_solution_edge_intensity(s, k, g) &
         bind(c, name="orthoslip_solution_edge_intensity") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(out) :: k, g
      integer(c_int) :: status
    end function

    ! Tangential surface displacement relative to the punch, per P/E.
    function orthoslip_solution_slip(s, x, n, slip) bind(c, name="orthoslip_solution_slip") &
         result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(in) :: x(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: slip(*)
      integer(c_int) :: status
    end function


    ! Tangential load and fretting (docs/fretting.md): per P/E, P^2/E; zone arrays hold
    ! 0 stick, +1 slip in +x, -1 slip in -x; cycle and step indices are 0-based.
    function orthoslip_cycle_options_new(out) &
         bind(c, name="orthoslip_cycle_options_new") result(status)
      import :: c_int, c_ptr
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    subroutine orthoslip_cycle_options_free(o) bind(c, name="orthoslip_cycle_options_free")
      import :: c_ptr
      type(c_ptr), value :: o
    end subroutine

    function orthoslip_cycle_options_set_method(o, method) &
         bind(c, name="orthoslip_cycle_options_set_method") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: o
      integer(c_int), value :: method
      integer(c_int) :: status
    end function

    function orthoslip_cycle_options_set_panels(o, panels) &
         bind(c, name="orthoslip_cycle_options_set_panels") result(status)
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: o
      integer(c_size_t), value :: panels
      integer(c_int) :: status
    end function

    function orthoslip_cycle_options_set_steps(o, steps) &
         bind(c, name="orthoslip_cycle_options_set_steps") result(status)
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: o
      integer(c_size_t), value :: steps
      integer(c_int) :: status
    end function

    function orthoslip_cycle_options_set_repeat_tolerance(o, tol) &
         bind(c, name="orthoslip_cycle_options_set_repeat_tolerance") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: o
      real(c_double), value :: tol
      integer(c_int) :: status
    end function

    function orthoslip_solution_stick_zone(s, c1, c2) &
         bind(c, name="orthoslip_solution_stick_zone") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(out) :: c1
      real(c_double), intent(out) :: c2
      integer(c_int) :: status
    end function

    function orthoslip_history_new(k, out) &
         bind(c, name="orthoslip_history_new") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: k
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    function orthoslip_history_new_with_options(k, o, out) &
         bind(c, name="orthoslip_history_new_with_options") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: k
      type(c_ptr), value :: o
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    subroutine orthoslip_history_free(h) bind(c, name="orthoslip_history_free")
      import :: c_ptr
      type(c_ptr), value :: h
    end subroutine

    function orthoslip_history_load(h, q_over_p) &
         bind(c, name="orthoslip_history_load") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: h
      real(c_double), value :: q_over_p
      integer(c_int) :: status
    end function

    function orthoslip_history_state(h, q_over_p, u, moment) &
         bind(c, name="orthoslip_history_state") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: h
      real(c_double), intent(out) :: q_over_p
      real(c_double), intent(out) :: u
      real(c_double), intent(out) :: moment
      integer(c_int) :: status
    end function

    function orthoslip_history_stick_zone(h, c1, c2, err) &
         bind(c, name="orthoslip_history_stick_zone") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: h
      real(c_double), intent(out) :: c1
      real(c_double), intent(out) :: c2
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    function orthoslip_history_tractions(h, x, n, p, q, zone) &
         bind(c, name="orthoslip_history_tractions") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: h
      real(c_double), intent(in) :: x(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: p(*)
      real(c_double), intent(out) :: q(*)
      integer(c_int), intent(out) :: zone(*)
      integer(c_int) :: status
    end function

    function orthoslip_history_dissipated_energy(h, w, err) &
         bind(c, name="orthoslip_history_dissipated_energy") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: h
      real(c_double), intent(out) :: w
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    function orthoslip_history_traction_error_estimate(h, err) &
         bind(c, name="orthoslip_history_traction_error_estimate") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: h
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    function orthoslip_contact_solve_cycles(k, q_amp_over_p, max_cycles, out) &
         bind(c, name="orthoslip_contact_solve_cycles") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: k
      real(c_double), value :: q_amp_over_p
      integer(c_size_t), value :: max_cycles
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    function orthoslip_contact_solve_cycles_with_options(k, o, q_amp_over_p, max_cycles, out) &
         bind(c, name="orthoslip_contact_solve_cycles_with_options") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: k
      type(c_ptr), value :: o
      real(c_double), value :: q_amp_over_p
      integer(c_size_t), value :: max_cycles
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    subroutine orthoslip_cycles_free(cy) bind(c, name="orthoslip_cycles_free")
      import :: c_ptr
      type(c_ptr), value :: cy
    end subroutine

    function orthoslip_cycles_count(cy, n, steady) &
         bind(c, name="orthoslip_cycles_count") result(status)
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), intent(out) :: n
      integer(c_int), intent(out) :: steady
      integer(c_int) :: status
    end function

    function orthoslip_cycles_method(cy, used) &
         bind(c, name="orthoslip_cycles_method") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: cy
      integer(c_int), intent(out) :: used
      integer(c_int) :: status
    end function

    function orthoslip_cycles_state(cy, state) &
         bind(c, name="orthoslip_cycles_state") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: cy
      integer(c_int), intent(out) :: state
      integer(c_int) :: status
    end function

    function orthoslip_cycles_dissipated_energy(cy, cycle, w) &
         bind(c, name="orthoslip_cycles_dissipated_energy") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(out) :: w
      integer(c_int) :: status
    end function

    function orthoslip_cycles_dissipated_energy_error(cy, cycle, err) &
         bind(c, name="orthoslip_cycles_dissipated_energy_error") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    function orthoslip_cycles_first_loading_energy(cy, w, err) &
         bind(c, name="orthoslip_cycles_first_loading_energy") result(status)
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: cy
      real(c_double), intent(out) :: w
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    function orthoslip_cycles_slip_amplitude(cy, cycle, x, n, amp) &
         bind(c, name="orthoslip_cycles_slip_amplitude") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(in) :: x(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: amp(*)
      integer(c_int) :: status
    end function

    function orthoslip_cycles_slip_amplitude_error(cy, cycle, err) &
         bind(c, name="orthoslip_cycles_slip_amplitude_error") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    function orthoslip_cycles_ruiz(cy, cycle, x, n, f1, f2) &
         bind(c, name="orthoslip_cycles_ruiz") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(in) :: x(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: f1(*)
      real(c_double), intent(out) :: f2(*)
      integer(c_int) :: status
    end function

    function orthoslip_cycles_stress_peaks(cy, cycle, x, n, tau_max, sxx_max) &
         bind(c, name="orthoslip_cycles_stress_peaks") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(in) :: x(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: tau_max(*)
      real(c_double), intent(out) :: sxx_max(*)
      integer(c_int) :: status
    end function

    function orthoslip_cycles_ruiz_peaks(cy, cycle, f1_max, x_f1, f2_max, x_f2, err) &
         bind(c, name="orthoslip_cycles_ruiz_peaks") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(out) :: f1_max
      real(c_double), intent(out) :: x_f1
      real(c_double), intent(out) :: f2_max
      real(c_double), intent(out) :: x_f2
      real(c_double), intent(out) :: err(*)
      integer(c_int) :: status
    end function

    function orthoslip_cycles_stick_zones(cy, cycle, c1_minus, c2_minus, c1_plus, c2_plus, err) &
         bind(c, name="orthoslip_cycles_stick_zones") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(out) :: c1_minus
      real(c_double), intent(out) :: c2_minus
      real(c_double), intent(out) :: c1_plus
      real(c_double), intent(out) :: c2_plus
      real(c_double), intent(out) :: err
      integer(c_int) :: status
    end function

    function orthoslip_cycles_loop_length(cy, cycle, len) &
         bind(c, name="orthoslip_cycles_loop_length") result(status)
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      integer(c_size_t), intent(out) :: len
      integer(c_int) :: status
    end function

    function orthoslip_cycles_loop(cy, cycle, len, q_over_p, u) &
         bind(c, name="orthoslip_cycles_loop") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      integer(c_size_t), value :: len
      real(c_double), intent(out) :: q_over_p(*)
      real(c_double), intent(out) :: u(*)
      integer(c_int) :: status
    end function

    function orthoslip_cycles_loop_error(cy, cycle, u_err, work_err) &
         bind(c, name="orthoslip_cycles_loop_error") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(out) :: u_err
      real(c_double), intent(out) :: work_err
      integer(c_int) :: status
    end function

    function orthoslip_cycles_energy_balance(cy, cycle, loop_work, normal_work, energy_change, residual) &
         bind(c, name="orthoslip_cycles_energy_balance") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      real(c_double), intent(out) :: loop_work
      real(c_double), intent(out) :: normal_work
      real(c_double), intent(out) :: energy_change
      real(c_double), intent(out) :: residual
      integer(c_int) :: status
    end function

    function orthoslip_cycles_step(cy, cycle, step, q_over_p, u, c1, c2) &
         bind(c, name="orthoslip_cycles_step") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      integer(c_size_t), value :: step
      real(c_double), intent(out) :: q_over_p
      real(c_double), intent(out) :: u
      real(c_double), intent(out) :: c1
      real(c_double), intent(out) :: c2
      integer(c_int) :: status
    end function

    function orthoslip_cycles_step_tractions(cy, cycle, step, x, n, p, q, zone) &
         bind(c, name="orthoslip_cycles_step_tractions") result(status)
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cy
      integer(c_size_t), value :: cycle
      integer(c_size_t), value :: step
      real(c_double), intent(in) :: x(*)
      integer(c_size_t), value :: n
      real(c_double), intent(out) :: p(*)
      real(c_double), intent(out) :: q(*)
      integer(c_int), intent(out) :: zone(*)
      integer(c_int) :: status
    end function

    function orthoslip_history_solution(h, out) &
         bind(c, name="orthoslip_history_solution") result(status)
      import :: c_int, c_ptr
      type(c_ptr), value :: h
      type(c_ptr), intent(out) :: out
      integer(c_int) :: status
    end function

    function c_strlen(str) bind(c, name="strlen") result(n)
      import :: c_size_t, c_ptr
      type(c_ptr), value :: str
      integer(c_size_t) :: n
    end function
  end interface

contains

  !> Copies a NUL-terminated C string into a Fortran string ("" for a null pointer).
  function from_c_string(str) result(f)
    type(c_ptr), intent(in) :: str
    character(len=:), allocatable :: f
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n

    if (.not. c_associated(str)) then
      f = ""
      return
    end if
    n = int(c_strlen(str))
    call c_f_pointer(str, chars, [n])
    allocate (character(len=n) :: f)
    do i = 1, n
      f(i:i) = chars(i)
    end do
  end function

  !> This thread's last error message.
  function last_error_message() result(msg)
    character(len=:), allocatable :: msg
    character(kind=c_char), allocatable, target :: buf(:)
    integer(c_size_t) :: n, ignored
    integer :: i

    n = orthoslip_last_error_message(c_null_ptr, 0_c_size_t)
    allocate (buf(n + 1))
    ignored = orthoslip_last_error_message(c_loc(buf), n + 1)
    allocate (character(len=n) :: msg)
    do i = 1, int(n)
      msg(i:i) = buf(i)
    end do
  end function

  !> The name of a status, e.g. "ORTHOSLIP_ERROR_NULL_POINTER".
  function status_name(status) result(name)
    integer(c_int), intent(in) :: status
    character(len=:), allocatable :: name
    name = from_c_string(orthoslip_status_string(status))
  end function

  !> The library version, e.g. "0.1.0".
  function version() result(v)
    character(len=:), allocatable :: v
    v = from_c_string(orthoslip_version())
  end function

end module orthoslip_mod
