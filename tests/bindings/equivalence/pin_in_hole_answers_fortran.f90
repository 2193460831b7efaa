! SPDX-License-Identifier: BSD-3-Clause
!> The Fortran binding's answers for the pin-in-hole equivalence test (README.md):
!> cj_detect_pin_in_hole on every record.
!>
!> usage: pin_in_hole_answers_fortran INPUT OUTPUT
program pin_in_hole_answers_fortran
  use clearjoint
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int32_t
  use, intrinsic :: iso_fortran_env, only: int64, error_unit
  implicit none
  integer, parameter :: record = 23
  character(len=4096) :: input_path, output_path
  real(c_double), allocatable :: data(:)
  type(cj_pin_in_hole_result) :: result
  type(cj_pin_in_hole_dimensions) :: dims
  type(cj_pose) :: hole, pin
  type(cj_options) :: options
  character(len=:), allocatable :: message
  integer :: unit, out, count, i, first
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
  open (newunit=out, file=trim(output_path), status='replace', action='write')

  do i = 0, count - 1
    first = (i + 1) * record  ! 0-based offset of the record, past the header
    dims = cj_pin_in_hole_dimensions()
    dims%hole_radius = data(first + 1)
    dims%hole_length = data(first + 2)
    dims%pin_radius = data(first + 3)
    dims%stop_count = int(data(first + 4), c_int32_t)
    dims%stops(1) = cj_axial_stop(data(first + 5), data(first + 6))
    dims%stops(2) = cj_axial_stop(data(first + 7), data(first + 8))
    hole = cj_pose(data(first + 9:first + 11), data(first + 12:first + 14))
    pin = cj_pose(data(first + 15:first + 17), data(first + 18:first + 20))
    options = cj_default_options()
    options%certify = merge(1_c_int32_t, 0_c_int32_t, data(first + 21) /= 0)
    options%parallel_angle_tolerance = data(first + 22)
    options%exact_fallback = merge(1_c_int32_t, 0_c_int32_t, data(first + 23) /= 0)
    status = cj_detect_pin_in_hole(dims, hole, pin, result, options, message)
    if (status == CJ_OK) then
      write (out, '(a)') result_line(i, result)
    else
      write (out, '(a)') 'S '//decimal(i)//' error '//decimal(status)//' '//message
    end if
  end do
  close (out)

contains

  include 'contact_line.inc'

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
