! The default scene through the Fortran bindings (orthoslip_mod): a carbon/epoxy ply (plane
! stress) under a rigid flat punch with mu = 0.3, then the first fretting cycle of Q between
! +-0.6 mu P. Every status is checked; on failure the library's message is printed and the
! program stops with exit code 1.
program default_scene
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_null_ptr
  use, intrinsic :: iso_fortran_env, only: error_unit
  use orthoslip_mod
  implicit none

  integer, parameter :: n = 21
  real(c_double), parameter :: e11 = 181e9_c_double, e22 = 10.3e9_c_double, &
       g12 = 7.17e9_c_double, nu12 = 0.28_c_double, mu = 0.3_c_double
  type(c_ptr) :: material = c_null_ptr, contact = c_null_ptr, solution = c_null_ptr
  type(c_ptr) :: options = c_null_ptr, cycles = c_null_ptr
  integer(c_size_t) :: n_cycles
  integer(c_int) :: steady
  real(c_double) :: w1, w1_error
  real(c_double) :: e, nu, delta, kappa, a, b, c_green, c, one_minus_c, c_error
  real(c_double) :: x(n), p(n), q(n)
  real(c_double) :: k, g, sxx(1), syy(1), sxy(1), slip(1)
  integer(c_int) :: used
  integer :: i

  print '(a)', 'orthoslip ' // version() // ' (Fortran)'
  call check(orthoslip_material_new_plane_stress(e11, e22, g12, nu12, material), &
       'orthoslip_material_new_plane_stress')
  call check(orthoslip_material_effective(material, e, nu, delta, kappa), &
       'orthoslip_material_effective')
  print '(4(a,es24.16e3))', 'effective: E = ', e, ', nu = ', nu, ', delta = ', delta, &
       ', kappa = ', kappa
  call check(orthoslip_material_green(material, a, b, c_green), 'orthoslip_material_green')
  print '(3(a,es24.16e3))', 'green: A = ', a, ', B = ', b, ', C = ', c_green

  call check(orthoslip_contact_new(material, contact), 'orthoslip_contact_new')
  call check(orthoslip_contact_set_friction(contact, mu), 'orthoslip_contact_set_friction')
  call check(orthoslip_contact_set_method(contact, ORTHOSLIP_METHOD_AUTO), &
       'orthoslip_contact_set_method')
  call check(orthoslip_contact_solve(contact, solution), 'orthoslip_contact_solve')

  call check(orthoslip_solution_stick_half_width(solution, c), &
       'orthoslip_solution_stick_half_width')
  call check(orthoslip_solution_slip_width(solution, one_minus_c), &
       'orthoslip_solution_slip_width')
  call check(orthoslip_solution_method(solution, used), 'orthoslip_solution_method')
  call check(orthoslip_solution_error_estimate(solution, c_error), &
       'orthoslip_solution_error_estimate')
  print '(a,es24.16e3)', 'c = ', c
  print '(a,es24.16e3)', '1 - c = ', one_minus_c
  print '(a,a)', 'method = ', method_name(used)
  print '(a,es10.3)', 'error estimate = ', c_error

  do i = 1, n
    x(i) = 0.99_c_double * real(i - 1 - n / 2, c_double) / real(n / 2, c_double)
  end do
  call check(orthoslip_solution_tractions(solution, x, int(n, c_size_t), p, q), &
       'orthoslip_solution_tractions')
  print '(a10,2a25)', 'x', 'p', 'q'
  do i = 1, n
    print '(f10.4,2es25.16e3)', x(i), p(i), q(i)
  end do

  call check(orthoslip_solution_edge_intensity(solution, k, g), &
       'orthoslip_solution_edge_intensity')
  call check(orthoslip_solution_stresses(solution, [0.0_c_double], [-0.5_c_double], 1_c_size_t, &
       sxx, syy, sxy), 'orthoslip_solution_stresses')
  call check(orthoslip_solution_slip(solution, [0.99_c_double], 1_c_size_t, slip), &
       'orthoslip_solution_slip')
  print '(2(a,es24.16e3))', 'edge intensity: k = ', k, ', g = ', g
  print '(3(a,es24.16e3))', 'stresses at (0, -0.5): sxx = ', sxx(1), ', syy = ', syy(1), &
       ', sxy = ', sxy(1)
  print '(a,es24.16e3)', 'slip at x = 0.99: ', slip(1)

  ! fretting: Q cycled between +-0.6 mu P on a coarse, quick grid (32 panels per half-width,
  ! 4 load steps per quarter cycle); energies per P^2/E
  call check(orthoslip_cycle_options_new(options), 'orthoslip_cycle_options_new')
  call check(orthoslip_cycle_options_set_panels(options, 32_c_size_t), &
       'orthoslip_cycle_options_set_panels')
  call check(orthoslip_cycle_options_set_steps(options, 4_c_size_t), &
       'orthoslip_cycle_options_set_steps')
  call check(orthoslip_contact_solve_cycles_with_options(contact, options, 0.6_c_double * mu, &
       10_c_size_t, cycles), 'orthoslip_contact_solve_cycles_with_options')
  call check(orthoslip_cycles_count(cycles, n_cycles, steady), 'orthoslip_cycles_count')
  call check(orthoslip_cycles_dissipated_energy(cycles, 0_c_size_t, w1), &
       'orthoslip_cycles_dissipated_energy')
  call check(orthoslip_cycles_dissipated_energy_error(cycles, 0_c_size_t, w1_error), &
       'orthoslip_cycles_dissipated_energy_error')
  print '(a,i0)', 'fretting cycles = ', n_cycles
  print '(a,es24.16e3)', 'fretting W1 = ', w1
  print '(a,es10.3e2)', 'fretting W1 error = ', w1_error

  call orthoslip_cycles_free(cycles)
  call orthoslip_cycle_options_free(options)
  call orthoslip_solution_free(solution)
  call orthoslip_contact_free(contact)
  call orthoslip_material_free(material)

contains

  subroutine check(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status /= ORTHOSLIP_OK) then
      write (error_unit, '(5a)') 'default_scene: ', what, ' failed: ', status_name(status), &
           ': ' // last_error_message()
      call orthoslip_cycles_free(cycles)
      call orthoslip_cycle_options_free(options)
      call orthoslip_solution_free(solution)
      call orthoslip_contact_free(contact)
      call orthoslip_material_free(material)
      error stop 1
    end if
  end subroutine

  function method_name(m) result(name)
    integer(c_int), intent(in) :: m
    character(len=:), allocatable :: name
    select case (m)
    case (ORTHOSLIP_METHOD_AUTO); name = 'AUTO'
    case (ORTHOSLIP_METHOD_GOODMAN); name = 'GOODMAN'
    case (ORTHOSLIP_METHOD_SPENCE); name = 'SPENCE'
    case (ORTHOSLIP_METHOD_COUPLED); name = 'COUPLED'
    case (ORTHOSLIP_METHOD_LCP); name = 'LCP'
    case default; name = 'unknown'
    end select
  end function

end program default_scene
