! SPDX-License-Identifier: BSD-3-Clause
!> Fortran binding of the clearjoint C API (clearjoint/clearjoint.h) through ISO_C_BINDING.
!>
!> The BIND(C) types below mirror the C structs field by field (same names, same layout); the
!> constants mirror the C enums. cj_detect and cj_detect_many (the paper's joint),
!> cj_detect_pin_in_hole and cj_detect_pin_in_hole_many (a pin through a hole) are Fortran
!> wrappers that return the C status and, when asked, the error message as a Fortran string.
!> See clearjoint.h for the meaning of every field and for the ABI rules.
module clearjoint
  use, intrinsic :: iso_c_binding, only: c_int, c_int32_t, c_double, c_char, c_ptr, c_size_t, &
                                         c_ptrdiff_t, c_null_char, c_null_ptr, c_loc, &
                                         c_f_pointer, c_associated, c_sizeof
  implicit none
  private

  ! cj_status
  integer(c_int), parameter, public :: CJ_OK = 0, CJ_INVALID_INPUT = 1, CJ_OUT_OF_MEMORY = 2, &
                                       CJ_INTERNAL_ERROR = 3
  ! The C enums' constants: the library's enum tables, written by scripts/projections
  ! (cmake --build build --target projections): edit the tables.
  ! BEGIN GENERATED enums
  ! cj_scenario (C++: ContactScenario)
  integer(c_int32_t), parameter, public :: CJ_SCENARIO_NONE = 0, CJ_SCENARIO_SINGLE_RADIAL = 1, &
    CJ_SCENARIO_SINGLE_AXIAL = 2, CJ_SCENARIO_RADIAL_AT_BOTH_BASES = 3, &
    CJ_SCENARIO_AXIAL_AT_BOTH_BASES = 4, CJ_SCENARIO_RADIAL_AND_AXIAL_SAME_BASE = 5, &
    CJ_SCENARIO_RADIAL_AND_AXIAL_OPPOSITE_BASES = 6, CJ_SCENARIO_TWO_RADIAL_ONE_AXIAL = 7, &
    CJ_SCENARIO_ONE_RADIAL_TWO_AXIAL = 8, CJ_SCENARIO_ALL_FOUR = 9, CJ_SCENARIO_LINE = 10, &
    CJ_SCENARIO_FACE = 11, CJ_SCENARIO_LINE_AND_FACE = 12, CJ_SCENARIO_BEYOND_MODEL = 13
  ! cj_certainty (C++: Certainty)
  integer(c_int32_t), parameter, public :: CJ_CERTAINTY_EXACT = 0, CJ_CERTAINTY_CERTIFIED = 1, &
    CJ_CERTAINTY_UNCERTAIN = 2
  ! cj_reason (C++: CertificateReason)
  integer(c_int32_t), parameter, public :: CJ_REASON_NONE = 0, CJ_REASON_NOT_DECIDED = 1, &
    CJ_REASON_CERTIFICATE_SWITCHED_OFF = 2, CJ_REASON_PLANE_FILTER_UNDECIDED = 3, &
    CJ_REASON_PLANE_FILTER_UNDECIDED_EXACT_FALLBACK_OFF = 4, &
    CJ_REASON_PLANE_RESULTS_NOT_REPRESENTABLE = 5, CJ_REASON_SUBDIVISION_BUDGET_EXHAUSTED = 6, &
    CJ_REASON_MORE_THAN_FOUR_ROOTS = 7, CJ_REASON_INTERVAL_PROOF_FAILED_NEAR_MULTIPLE_ROOT = 8, &
    CJ_REASON_COEFFICIENT_OVERFLOW = 9, CJ_REASON_CYLINDER_POINTS_NOT_REPRESENTABLE = 10, &
    CJ_REASON_EXACT_ROOT_ISOLATION_BUDGET_EXHAUSTED = 11, &
    CJ_REASON_EXACT_COEFFICIENTS_TOO_LARGE = 12, &
    CJ_REASON_EXACT_INTERMEDIATE_BEYOND_DOUBLE_RANGE = 13, &
    CJ_REASON_CONTACT_NOT_REPRESENTABLE_IN_WORLD = 14, &
    CJ_REASON_AXES_PARALLEL_WITHIN_TOLERANCE = 15, CJ_REASON_BEYOND_MODEL_UNDECIDED = 16, &
    CJ_REASON_EDGE_SIDES_UNDECIDED = 17
  ! cj_contact_type (C++: ContactType)
  integer(c_int32_t), parameter, public :: CJ_CONTACT_RADIAL = 0, CJ_CONTACT_AXIAL = 1
  ! cj_base (C++: ContactBase)
  integer(c_int32_t), parameter, public :: CJ_BASE_A = 0, CJ_BASE_B = 1, CJ_BASE_MID = 2
  ! cj_circle_plane_topology (C++: CirclePlaneTopology)
  integer(c_int32_t), parameter, public :: CJ_CIRCLE_PLANE_DISJOINT = 0, &
    CJ_CIRCLE_PLANE_TANGENT = 1, CJ_CIRCLE_PLANE_TWO_CROSSINGS = 2, &
    CJ_CIRCLE_PLANE_CIRCLE_IN_PLANE = 3
  ! cj_circle_cylinder_topology (C++: CircleCylinderTopology)
  integer(c_int32_t), parameter, public :: CJ_CIRCLE_CYLINDER_INSIDE = 0, &
    CJ_CIRCLE_CYLINDER_OUTSIDE = 1, CJ_CIRCLE_CYLINDER_CROSSING = 2, &
    CJ_CIRCLE_CYLINDER_ON_SURFACE = 3
  ! cj_pin_in_hole_scenario (C++: PinInHoleScenario)
  integer(c_int32_t), parameter, public :: CJ_PIN_IN_HOLE_NONE = 0, CJ_PIN_IN_HOLE_ONE_EDGE = 1, &
    CJ_PIN_IN_HOLE_BOTH_EDGES_OPPOSITE = 2, CJ_PIN_IN_HOLE_BOTH_EDGES_SAME_SIDE = 3, &
    CJ_PIN_IN_HOLE_LINE = 4, CJ_PIN_IN_HOLE_ONE_STOP = 5, CJ_PIN_IN_HOLE_BOTH_STOPS = 6, &
    CJ_PIN_IN_HOLE_FACE = 7, CJ_PIN_IN_HOLE_EDGES_AND_STOPS = 8, CJ_PIN_IN_HOLE_LINE_AND_FACE = 9, &
    CJ_PIN_IN_HOLE_BEYOND_MODEL = 10
  ! END GENERATED enums
  integer, parameter, public :: CJ_MAX_CONTACTS = 6

  type, bind(c), public :: cj_dimensions
    real(c_double) :: bearing_radius, bearing_length, journal_radius, journal_length
  end type

  type, bind(c), public :: cj_pose
    real(c_double) :: p_WP(3), axis_W(3)
  end type

  type, bind(c), public :: cj_options
    integer(c_int32_t) :: certify, exact_fallback
    real(c_double) :: parallel_angle_tolerance
    real(c_double) :: reserved(4)
  end type

  !> An axial stop of a pin: see cj_axial_stop in clearjoint.h.
  type, bind(c), public :: cj_axial_stop
    real(c_double) :: position, outer_radius
  end type

  integer, parameter, public :: CJ_MAX_AXIAL_STOPS = 2

  !> A pin through a hole: see cj_pin_in_hole_dimensions in clearjoint.h; stops(1:stop_count)
  !> are read, the reserved members must be zero (as the default initialisation leaves them).
  type, bind(c), public :: cj_pin_in_hole_dimensions
    real(c_double) :: hole_radius = 0, hole_length = 0, pin_radius = 0
    integer(c_int32_t) :: stop_count = 0
    integer(c_int32_t) :: reserved0 = 0
    type(cj_axial_stop) :: stops(CJ_MAX_AXIAL_STOPS) = cj_axial_stop(0, 0)
    real(c_double) :: reserved(4) = 0
  end type

  type, bind(c), public :: cj_certificate
    ! BEGIN GENERATED cj_certificate components: the C struct's members, from scripts/projections
    integer(c_int32_t) :: level
    integer(c_int32_t) :: reason
    type(c_ptr) :: reason_text  ! static C string: cj_string(reason_text)
    ! END GENERATED cj_certificate components
  end type

  type, bind(c), public :: cj_crossing
    ! BEGIN GENERATED cj_crossing components: the C struct's members, from scripts/projections
    real(c_double) :: angle
    real(c_double) :: angle_error_bound
    real(c_double) :: point(3)
    real(c_double) :: point_error_bound
    integer(c_int32_t) :: multiplicity
    integer(c_int32_t) :: reserved
    ! END GENERATED cj_crossing components
  end type

  type, bind(c), public :: cj_contact
    ! BEGIN GENERATED cj_contact components: the C struct's members, from scripts/projections
    integer(c_int32_t) :: type
    integer(c_int32_t) :: base
    real(c_double) :: p_WCj(3)
    real(c_double) :: p_WCi(3)
    real(c_double) :: normal_W(3)
    real(c_double) :: depth
    real(c_double) :: depth_error_bound
    real(c_double) :: p_WCj_error_bound
    real(c_double) :: p_WCi_error_bound
    type(cj_crossing) :: crossings(2)
    integer(c_int32_t) :: crossing_count
    integer(c_int32_t) :: reserved0
    type(cj_certificate) :: certificate
    real(c_double) :: reserved(4)
    ! END GENERATED cj_contact components
  end type

  type, bind(c), public :: cj_result
    ! BEGIN GENERATED cj_result components: the C struct's members, from scripts/projections
    integer(c_int32_t) :: scenario
    integer(c_int32_t) :: aligned
    integer(c_int32_t) :: contact_count
    integer(c_int32_t) :: reserved0
    type(cj_certificate) :: certificate
    type(cj_contact) :: contacts(CJ_MAX_CONTACTS)
    real(c_double) :: reserved(8)
    ! END GENERATED cj_result components
  end type

  type, bind(c), public :: cj_pin_in_hole_result
    ! BEGIN GENERATED cj_pin_in_hole_result components: the C struct's members, from scripts/projections
    integer(c_int32_t) :: scenario
    integer(c_int32_t) :: aligned
    integer(c_int32_t) :: contact_count
    integer(c_int32_t) :: reserved0
    type(cj_certificate) :: certificate
    type(cj_contact) :: contacts(CJ_MAX_CONTACTS)
    real(c_double) :: reserved(8)
    ! END GENERATED cj_pin_in_hole_result components
  end type

  type, bind(c), public :: cj_pose_array
    type(c_ptr) :: component(6)
    integer(c_ptrdiff_t) :: stride
  end type

  public :: cj_detect, cj_detect_many, cj_default_options, cj_version, cj_string
  public :: cj_scenario_string, cj_certainty_string, cj_contact_type_string, cj_base_string
  public :: cj_detect_pin_in_hole, cj_detect_pin_in_hole_many, cj_pin_in_hole_scenario_string

  interface
    function c_detect(dimensions, bearing, journal, options, result, message, capacity) &
        bind(c, name="cj_detect") result(status)
      import :: c_int, c_ptr, c_char, c_size_t, cj_dimensions, cj_pose, cj_result
      type(cj_dimensions), intent(in) :: dimensions
      type(cj_pose), intent(in) :: bearing, journal
      type(c_ptr), value :: options
      type(cj_result), intent(inout) :: result
      character(kind=c_char), dimension(*), intent(out) :: message
      integer(c_size_t), value :: capacity
      integer(c_int) :: status
    end function

    function c_detect_many(dimensions, bearings, journals, count, options, results, processed, &
                           message, capacity) bind(c, name="cj_detect_many") result(status)
      import :: c_int, c_ptr, c_char, c_size_t, cj_dimensions, cj_pose_array, cj_result
      type(cj_dimensions), intent(in) :: dimensions
      type(cj_pose_array), intent(in) :: bearings, journals
      integer(c_size_t), value :: count
      type(c_ptr), value :: options
      type(cj_result), intent(inout) :: results(*)
      integer(c_size_t), intent(out) :: processed
      character(kind=c_char), dimension(*), intent(out) :: message
      integer(c_size_t), value :: capacity
      integer(c_int) :: status
    end function

    function c_detect_pin_in_hole(dimensions, hole, pin, options, result, message, capacity) &
        bind(c, name="cj_detect_pin_in_hole") result(status)
      import :: c_int, c_ptr, c_char, c_size_t, cj_pin_in_hole_dimensions, cj_pose, cj_pin_in_hole_result
      type(cj_pin_in_hole_dimensions), intent(in) :: dimensions
      type(cj_pose), intent(in) :: hole, pin
      type(c_ptr), value :: options
      type(cj_pin_in_hole_result), intent(inout) :: result
      character(kind=c_char), dimension(*), intent(out) :: message
      integer(c_size_t), value :: capacity
      integer(c_int) :: status
    end function

    function c_detect_pin_in_hole_many(dimensions, holes, pins, count, options, results, processed, &
                                       message, capacity) bind(c, name="cj_detect_pin_in_hole_many") &
        result(status)
      import :: c_int, c_ptr, c_char, c_size_t, cj_pin_in_hole_dimensions, cj_pose_array, &
                cj_pin_in_hole_result
      type(cj_pin_in_hole_dimensions), intent(in) :: dimensions
      type(cj_pose_array), intent(in) :: holes, pins
      integer(c_size_t), value :: count
      type(c_ptr), value :: options
      type(cj_pin_in_hole_result), intent(inout) :: results(*)
      integer(c_size_t), intent(out) :: processed
      character(kind=c_char), dimension(*), intent(out) :: message
      integer(c_size_t), value :: capacity
      integer(c_int) :: status
    end function

    function c_pin_in_hole_scenario_string(code) bind(c, name="cj_pin_in_hole_scenario_string") result(text)
      import :: c_ptr, c_int
      integer(c_int), value :: code
      type(c_ptr) :: text
    end function

    function cj_default_options() bind(c, name="cj_default_options") result(options)
      import :: cj_options
      type(cj_options) :: options
    end function

    function c_version() bind(c, name="cj_version") result(text)
      import :: c_ptr
      type(c_ptr) :: text
    end function

    function c_scenario_string(code) bind(c, name="cj_scenario_string") result(text)
      import :: c_ptr, c_int
      integer(c_int), value :: code
      type(c_ptr) :: text
    end function

    function c_certainty_string(code) bind(c, name="cj_certainty_string") result(text)
      import :: c_ptr, c_int
      integer(c_int), value :: code
      type(c_ptr) :: text
    end function

    function c_contact_type_string(code) bind(c, name="cj_contact_type_string") result(text)
      import :: c_ptr, c_int
      integer(c_int), value :: code
      type(c_ptr) :: text
    end function

    function c_base_string(code) bind(c, name="cj_base_string") result(text)
      import :: c_ptr, c_int
      integer(c_int), value :: code
      type(c_ptr) :: text
    end function

    pure function c_strlen(text) bind(c, name="strlen") result(length)
      import :: c_ptr, c_size_t
      type(c_ptr), value, intent(in) :: text
      integer(c_size_t) :: length
    end function
  end interface

  !> Capacity of the message buffer the wrappers pass to the C API.
  integer(c_size_t), parameter :: message_capacity = 1024

contains

  !> A NUL-terminated C string (a static string of the library) as a Fortran string.
  function cj_string(text) result(out)
    type(c_ptr), intent(in) :: text
    character(len=:), allocatable :: out
    character(kind=c_char), pointer :: chars(:)
    integer :: k, length
    if (.not. c_associated(text)) then
      out = ''
      return
    end if
    length = int(c_strlen(text))
    call c_f_pointer(text, chars, [length])
    allocate(character(len=length) :: out)
    do k = 1, length
      out(k:k) = chars(k)
    end do
  end function

  !> The message the C API wrote into `buffer`, up to its NUL.
  function message_text(buffer) result(out)
    character(kind=c_char, len=*), intent(in) :: buffer
    character(len=:), allocatable :: out
    integer :: length
    length = index(buffer, c_null_char) - 1
    if (length < 0) length = len(buffer)
    out = buffer(1:length)
  end function

  function cj_version() result(out)
    character(len=:), allocatable :: out
    out = cj_string(c_version())
  end function

  function cj_scenario_string(code) result(out)
    integer(c_int32_t), intent(in) :: code
    character(len=:), allocatable :: out
    out = cj_string(c_scenario_string(int(code, c_int)))
  end function

  function cj_certainty_string(code) result(out)
    integer(c_int32_t), intent(in) :: code
    character(len=:), allocatable :: out
    out = cj_string(c_certainty_string(int(code, c_int)))
  end function

  function cj_contact_type_string(code) result(out)
    integer(c_int32_t), intent(in) :: code
    character(len=:), allocatable :: out
    out = cj_string(c_contact_type_string(int(code, c_int)))
  end function

  function cj_base_string(code) result(out)
    integer(c_int32_t), intent(in) :: code
    character(len=:), allocatable :: out
    out = cj_string(c_base_string(int(code, c_int)))
  end function

  !> Detect the contacts of one joint (C: cj_detect). Returns the status; on failure `result` is
  !> untouched and `message` (when present) holds the reason, naming the field and its value.
  function cj_detect(dimensions, bearing, journal, result, options, message) result(status)
    type(cj_dimensions), intent(in) :: dimensions
    type(cj_pose), intent(in) :: bearing, journal
    type(cj_result), intent(inout) :: result
    type(cj_options), intent(in), target, optional :: options
    character(len=:), allocatable, intent(out), optional :: message
    integer(c_int) :: status
    character(kind=c_char, len=message_capacity) :: buffer
    status = c_detect(dimensions, bearing, journal, options_address(options), result, buffer, &
                      message_capacity)
    if (present(message)) message = message_text(buffer)
  end function

  function cj_pin_in_hole_scenario_string(code) result(out)
    integer(c_int32_t), intent(in) :: code
    character(len=:), allocatable :: out
    out = cj_string(c_pin_in_hole_scenario_string(int(code, c_int)))
  end function

  !> Detect the contacts of a pin in its hole (C: cj_detect_pin_in_hole). Returns the status; on
  !> failure `result` is untouched and `message` (when present) holds the reason, naming the
  !> field and its value.
  function cj_detect_pin_in_hole(dimensions, hole, pin, result, options, message) result(status)
    type(cj_pin_in_hole_dimensions), intent(in) :: dimensions
    type(cj_pose), intent(in) :: hole, pin
    type(cj_pin_in_hole_result), intent(inout) :: result
    type(cj_options), intent(in), target, optional :: options
    character(len=:), allocatable, intent(out), optional :: message
    integer(c_int) :: status
    character(kind=c_char, len=message_capacity) :: buffer
    status = c_detect_pin_in_hole(dimensions, hole, pin, options_address(options), result, buffer, &
                                  message_capacity)
    if (present(message)) message = message_text(buffer)
  end function

  !> Detect the contacts of n poses (C: cj_detect_many). bearings and journals hold one pose
  !> [p_WP, axis_W] per column, shape (6, n), read in place; a single column (6, 1) serves every
  !> pose. results(1:n) receive the answers; on failure the results before the failing pose are
  !> set and `message` names it (poses numbered from 0, as in C).
  function cj_detect_many(dimensions, bearings, journals, results, options, message) result(status)
    type(cj_dimensions), intent(in) :: dimensions
    real(c_double), intent(in), target, contiguous :: bearings(:, :), journals(:, :)
    type(cj_result), intent(inout) :: results(:)
    type(cj_options), intent(in), target, optional :: options
    character(len=:), allocatable, intent(out), optional :: message
    integer(c_int) :: status
    character(kind=c_char, len=message_capacity) :: buffer
    character(len=:), allocatable :: refusal
    integer(c_size_t) :: processed
    if (batch_settled(bearings, journals, size(results), 'bearings and journals', status, refusal)) then
      if (present(message)) message = refusal
      return
    end if
    status = c_detect_many(dimensions, columns_of(bearings), columns_of(journals), &
                           int(size(results), c_size_t), options_address(options), results, &
                           processed, buffer, message_capacity)
    if (present(message)) message = message_text(buffer)
  end function

  !> Detect the contacts of a pin in its hole over n poses (C: cj_detect_pin_in_hole_many), as
  !> cj_detect_many does for the paper's joint: holes and pins of shape (6, n) or (6, 1), one
  !> pose [p_WP, axis_W] per column, read in place; results(k) is bit for bit the answer of
  !> cj_detect_pin_in_hole on pose k. On failure the results before the failing pose are set and
  !> `message` names it (poses numbered from 0, as in C).
  function cj_detect_pin_in_hole_many(dimensions, holes, pins, results, options, message) result(status)
    type(cj_pin_in_hole_dimensions), intent(in) :: dimensions
    real(c_double), intent(in), target, contiguous :: holes(:, :), pins(:, :)
    type(cj_pin_in_hole_result), intent(inout) :: results(:)
    type(cj_options), intent(in), target, optional :: options
    character(len=:), allocatable, intent(out), optional :: message
    integer(c_int) :: status
    character(kind=c_char, len=message_capacity) :: buffer
    character(len=:), allocatable :: refusal
    integer(c_size_t) :: processed
    if (batch_settled(holes, pins, size(results), 'holes and pins', status, refusal)) then
      if (present(message)) message = refusal
      return
    end if
    status = c_detect_pin_in_hole_many(dimensions, columns_of(holes), columns_of(pins), &
                                       int(size(results), c_size_t), options_address(options), &
                                       results, processed, buffer, message_capacity)
    if (present(message)) message = message_text(buffer)
  end function

  !> The options' address for the C API, or NULL (its defaults) when they are absent.
  function options_address(options) result(address)
    type(cj_options), intent(in), target, optional :: options
    type(c_ptr) :: address
    address = c_null_ptr
    if (present(options)) address = c_loc(options)
  end function

  !> Whether a batch call is answered before the C API is called: two pose arrays (`names`, as
  !> the caller's arguments) not of shape (6, n) or (6, 1) give CJ_INVALID_INPUT and a message
  !> naming them, n = 0 gives CJ_OK (nothing to read: the arrays may be empty). The message is a
  !> plain allocatable, not the callers' optional one: gfortran 12 loses the length of an
  !> optional deferred-length string passed on to another procedure (GCC bug 93762).
  function batch_settled(first, second, n, names, status, message) result(settled)
    real(c_double), intent(in) :: first(:, :), second(:, :)
    integer, intent(in) :: n
    character(len=*), intent(in) :: names
    integer(c_int), intent(out) :: status
    character(len=:), allocatable, intent(out) :: message
    logical :: settled
    settled = .true.
    status = CJ_OK
    message = ''
    if (size(first, 1) /= 6 .or. size(second, 1) /= 6 .or. &
        (size(first, 2) /= 1 .and. size(first, 2) /= n) .or. &
        (size(second, 2) /= 1 .and. size(second, 2) /= n)) then
      status = CJ_INVALID_INPUT
      message = names//': must have shape (6, size(results)) or (6, 1)'
    else if (n > 0) then
      settled = .false.
    end if
  end function

  !> Poses stored one per column of a (6, n) array: C's row-major n x 6 layout; one column
  !> repeats (stride 0).
  function columns_of(poses) result(array)
    real(c_double), intent(in), target, contiguous :: poses(:, :)
    type(cj_pose_array) :: array
    integer :: c
    do c = 1, 6
      array%component(c) = c_loc(poses(c, 1))
    end do
    array%stride = 0
    if (size(poses, 2) > 1) array%stride = 6 * c_sizeof(poses(1, 1))
  end function

end module clearjoint
