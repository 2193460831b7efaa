! SPDX-License-Identifier: BSD-3-Clause
!> The Fortran binding's answers for the pin-in-hole equivalence test (README.md):
!> cj_detect_pin_in_hole on every record, and cj_detect_pin_in_hole_many on the random poses
!> (copied into (6, n) arrays, the layout the Fortran wrapper takes), whose answers must be the
!> single calls' bit for bit (exits with status 1 otherwise).
!>
!> usage: pin_in_hole_answers_fortran INPUT OUTPUT
program pin_in_hole_answers_fortran
  use clearjoint
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int32_t
  use, intrinsic :: iso_fortran_env, only: int64, error_unit
  implicit none
  integer, parameter :: record = 23
  character(len=4096) :: input_path, output_path
  real(c_double), allocatable :: data(:), holes(:, :), pins(:, :)
  type(cj_pin_in_hole_result) :: result
  type(cj_pin_in_hole_result), allocatable :: singles_of_batch(:), results(:)
  type(cj_pin_in_hole_dimensions) :: dims
  type(cj_pose) :: hole, pin
  type(cj_options) :: options
  character(len=:), allocatable :: message
  integer :: unit, out, count, singles, batch, i, k, first, differences
  integer(int64) :: bytes
  integer(c_int) :: status

  if (command_argument_count() /= 2) then
    write (error_unit, '(a)') 'usage: pin_in_hole_answers_fortran INPUT OUTPUT'
    stop 2
  end if
  call get_command_argument(1, input_path)
  call get_command_argument(2, output_path)
  open (newunit=unit, file=trim(input_path), access='stream', form='unformatted', status='old', &
        action='read')
  inquire (unit=unit, size=bytes)
  allocate (data(bytes / 8))
  read (unit) data
  close (unit)
  count = nint(data(1))
  singles = nint(data(2))
  batch = count - singles
  allocate (singles_of_batch(batch))
  open (newunit=out, file=trim(output_path), status='replace', action='write')

  do i = 0, count - 1
    first = (i + 1) * record  ! 0-based offset of the record, past the header
    dims = dimensions_at(first)
    hole = cj_pose(data(first + 9:first + 11), data(first + 12:first + 14))
    pin = cj_pose(data(first + 15:first + 17), data(first + 18:first + 20))
    options = cj_default_options()
    options%certify = merge(1_c_int32_t, 0_c_int32_t, data(first + 21) /= 0)
    options%parallel_angle_tolerance = data(first + 22)
    options%exact_fallback = merge(1_c_int32_t, 0_c_int32_t, data(first + 23) /= 0)
    status = cj_detect_pin_in_hole(dims, hole, pin, result, options, message)
    if (status == CJ_OK) then
      write (out, '(a)') result_line(i, result)
      if (i >= singles) singles_of_batch(i - singles + 1) = result
    else
      write (out, '(a)') 'S '//decimal(i)//' error '//decimal(status)//' '//message
    end if
  end do
  close (out)

  ! The random poses (one joint, the default options) through the batch call.
  if (batch > 0) then
    allocate (holes(6, batch), pins(6, batch), results(batch))
    do k = 1, batch
      first = (singles + k) * record
      holes(:, k) = data(first + 9:first + 14)
      pins(:, k) = data(first + 15:first + 20)
    end do
    first = (singles + 1) * record
    dims = dimensions_at(first)
    status = cj_detect_pin_in_hole_many(dims, holes, pins, results, message=message)
    if (status /= CJ_OK) then
      write (error_unit, '(a)') 'cj_detect_pin_in_hole_many failed: '//message
      stop 1
    end if
    differences = 0
    do k = 1, batch
      if (result_line(singles + k - 1, results(k)) /= result_line(singles + k - 1, singles_of_batch(k))) then
        write (error_unit, '(a)') 'pose '//decimal(singles + k - 1)// &
          ': cj_detect_pin_in_hole_many and cj_detect_pin_in_hole differ'
        differences = differences + 1
      end if
    end do
    if (differences > 0) stop 1
    ! Pose arrays of another shape are refused by the wrapper, naming them.
    status = cj_detect_pin_in_hole_many(dims, holes(1:5, :), pins, results, message=message)
    if (status /= CJ_INVALID_INPUT .or. index(message, 'holes and pins: must have shape') /= 1) then
      write (error_unit, '(a)') 'holes(1:5, :): status '//decimal(status)//', message "'//message//'"'
      stop 1
    end if
    write (*, '(a)') decimal(batch)//' batch poses: cj_detect_pin_in_hole_many gives the single '// &
      'answers bit for bit'
  end if

contains

  include 'contact_line.inc'

  !> The joint of the record at 0-based offset `first`.
  function dimensions_at(first) result(d)
    integer, intent(in) :: first
    type(cj_pin_in_hole_dimensions) :: d
    d%hole_radius = data(first + 1)
    d%hole_length = data(first + 2)
    d%pin_radius = data(first + 3)
    d%stop_count = int(data(first + 4), c_int32_t)
    d%stops(1) = cj_axial_stop(data(first + 5), data(first + 6))
    d%stops(2) = cj_axial_stop(data(first + 7), data(first + 8))
  end function

  function result_line(index, r) result(line)
    integer, intent(in) :: index
    type(cj_pin_in_hole_result), intent(in) :: r
    character(len=:), allocatable :: line
    integer :: k
    line = 'S '//decimal(index)//' ok '//decimal(r%scenario)//' '//decimal(r%aligned)//' '// &
           decimal(r%certificate%level)//' '//decimal(r%certificate%reason)//' "'// &
           cj_string(r%certificate%reason_text)//'" '//decimal(r%contact_count)
    do k = 1, r%contact_count
      line = line//contact_text(r%contacts(k), .true.)
    end do
  end function

end program
