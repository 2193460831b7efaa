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

  function decimal(n) result(text)
    integer, intent(in) :: n
    character(len=:), allocatable :: text
    character(len=24) :: buffer
    write (buffer, '(i0)') n
    text = trim(buffer)
  end function

  !> IEEE bits of x as 16 upper-case hex digits, after a space.
  function hex(x) result(text)
    real(c_double), intent(in) :: x
    character(len=17) :: text
    write (text, '(1x, z16.16)') transfer(x, 0_int64)
  end function

  function hex3(v) result(text)
    real(c_double), intent(in) :: v(3)
    character(len=51) :: text
    text = hex(v(1))//hex(v(2))//hex(v(3))
  end function

  function result_line(index, r) result(line)
    integer, intent(in) :: index
    type(cj_pin_in_hole_result), intent(in) :: r
    character(len=:), allocatable :: line
    integer :: k, m
    line = 'S '//decimal(index)//' ok '//decimal(r%scenario)//' '//decimal(r%aligned)//' '// &
           decimal(r%certificate%level)//' '//decimal(r%certificate%reason)//' "'// &
           cj_string(r%certificate%reason_text)//'" '//decimal(r%contact_count)
    do k = 1, r%contact_count
      associate (c => r%contacts(k))
        line = line//' | '//decimal(c%type)//' '//decimal(c%base)//hex(c%depth)//hex3(c%p_WCj)// &
               hex3(c%p_WCi)//hex3(c%normal_W)//hex(c%depth_error_bound)//hex(c%p_WCj_error_bound)// &
               hex(c%p_WCi_error_bound)//' '//decimal(c%crossing_count)
        do m = 1, c%crossing_count
          associate (x => c%crossings(m))
            line = line//hex(x%angle)//hex(x%angle_error_bound)//hex3(x%point)// &
                   hex(x%point_error_bound)//' '//decimal(x%multiplicity)
          end associate
        end do
        line = line//' '//decimal(c%certificate%level)//' '//decimal(c%certificate%reason)//' "'// &
               cj_string(c%certificate%reason_text)//'"'
      end associate
    end do
  end function

end program
