! SPDX-License-Identifier: BSD-3-Clause
!> Detects the contacts of the paper's joint (Marques et al. 2017, Table 2, in millimetres) with
!> the journal tilted and pushed towards the wall and base A: scenario (e), a radial and an axial
!> contact at base A. Exits with status 1 unless that is the answer.
program example_paper_joint
  use clearjoint
  use, intrinsic :: iso_c_binding, only: c_double
  implicit none
  type(cj_dimensions) :: joint
  type(cj_pose) :: bearing, journal
  type(cj_result) :: found
  character(len=:), allocatable :: message
  integer :: k
  real(c_double), parameter :: tilt = 0.005d0

  joint = cj_dimensions(bearing_radius=10d0, bearing_length=20d0, journal_radius=9.9d0, &
                        journal_length=19.8d0)
  bearing = cj_pose(p_WP=[0d0, 0d0, 0d0], axis_W=[0d0, 0d0, 1d0])
  journal = cj_pose(p_WP=[0d0, 0.08d0, 0.08d0], axis_W=[0d0, sin(tilt), cos(tilt)])

  if (cj_detect(joint, bearing, journal, found, message=message) /= CJ_OK) then
    print '(a)', 'cj_detect failed: '//message
    stop 1
  end if
  print '(a, a)', 'clearjoint ', cj_version()
  print '(a, a, a, a)', 'scenario: ', cj_scenario_string(found%scenario), ', certificate: ', &
    cj_certainty_string(found%certificate%level)
  do k = 1, found%contact_count
    associate (c => found%contacts(k))
      print '(a, a, a, a, a, es12.5, a, 3es13.5)', '  ', cj_contact_type_string(c%type), &
        ' at base ', cj_base_string(c%base), ': depth ', c%depth, ', journal point ', c%p_WCj
    end associate
  end do
  if (found%scenario /= CJ_SCENARIO_RADIAL_AND_AXIAL_SAME_BASE .or. found%contact_count /= 2) stop 1
end program
