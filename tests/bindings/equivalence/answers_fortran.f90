! SPDX-License-Identifier: BSD-3-Clause
!> The Fortran binding's answers for the equivalence test (README.md): cj_detect on the
!> single-call records, cj_detect_many on the batch records (copied into (6, n) arrays, the
!> layout the Fortran wrapper takes).
!>
!> usage: answers_fortran INPUT OUTPUT
program answers_fortran
  use clearjoint
  use, intrinsic :: iso_c_binding, only: c_double, c_int, c_int32_t
  use, intrinsic :: iso_fortran_env, only: int64, error_unit
  implicit none
  integer, parameter :: record = 19
  character(len=4096) :: input_path, output_path
  real(c_double), allocatable :: data(:), bearings(:, :), journals(:, :)
  type(cj_result), allocatable :: results(:)
  type(cj_result) :: single
  type(cj_dimensions) :: dims
  type(cj_pose) :: bearing, journal
  type(cj_options) :: options
  character(len=:), allocatable :: message
  integer :: unit, out, count, singles, batch, i, k, first
  integer(int64) :: bytes
  integer(c_int) :: status

  if (command_argument_count() /= 2) then
    write (error_unit, '(a)') 'usage: answers_fortran INPUT OUTPUT'
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
  open (newunit=out, file=trim(output_path), status='replace', action='write')

  do i = 0, singles - 1
    first = (i + 1) * record  ! 0-based offset of the record, past the header
    dims = cj_dimensions(data(first + 1), data(first + 2), data(first + 3), data(first + 4))
    bearing = cj_pose(data(first + 5:first + 7), data(first + 8:first + 10))
    journal = cj_pose(data(first + 11:first + 13), data(first + 14:first + 16))
    options = cj_default_options()
    options%certify = merge(1_c_int32_t, 0_c_int32_t, data(first + 17) /= 0)
    options%parallel_angle_tolerance = data(first + 18)
    options%exact_fallback = merge(1_c_int32_t, 0_c_int32_t, data(first + 19) /= 0)
    status = cj_detect(dims, bearing, journal, single, options, message)
    if (status == CJ_OK) then
      write (out, '(a)') result_line('S', i, single)
    else
      write (out, '(a)') 'S '//decimal(i)//' error '//decimal(status)//' '//message
    end if
  end do

  batch = count - singles
  if (batch > 0) then
    allocate (bearings(6, batch), journals(6, batch), results(batch))
    do k = 1, batch
      first = (singles + k) * record
      bearings(:, k) = data(first + 5:first + 10)
      journals(:, k) = data(first + 11:first + 16)
    end do
    first = (singles + 1) * record
    dims = cj_dimensions(data(first + 1), data(first + 2), data(first + 3), data(first + 4))
    status = cj_detect_many(dims, bearings, journals, results, message=message)
    if (status /= CJ_OK) then
      write (error_unit, '(a)') 'cj_detect_many failed: '//message
      stop 1
    end if
    do k = 1, batch
      write (out, '(a)') result_line('B', singles + k - 1, results(k))
    end do
    ! Pose arrays of another shape are refused by the wrapper, naming them.
    status = cj_detect_many(dims, bearings, journals(1:5, :), results, message=message)
    if (status /= CJ_INVALID_INPUT .or. index(message, 'bearings and journals: must have shape') /= 1) then
      write (error_unit, '(a)') 'journals(1:5, :): status '//decimal(status)//', message "'//message//'"'
      stop 1
    end if
  end if
  close (out)

contains

  include 'contact_line.inc'

  function result_line(tag, index, r) result(line)
    character, intent(in) :: tag
    integer, intent(in) :: index
    type(cj_result), intent(in) :: r
    character(len=:), allocatable :: line
    integer :: k
    line = tag//' '//decimal(index)//' ok '//decimal(r%scenario)//' '//decimal(r%aligned)//' '// &
           decimal(r%certificate%level)//' '//decimal(r%certificate%reason)
    if (tag == 'S') line = line//' "'//cj_string(r%certificate%reason_text)//'"'
    line = line//' '//decimal(r%contact_count)
    do k = 1, r%contact_count
      line = line//contact_text(r%contacts(k), tag == 'S')
    end do
  end function

end program
