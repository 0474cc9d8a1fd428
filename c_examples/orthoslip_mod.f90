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
