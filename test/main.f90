!> kinetostat's Fortran test program: physics and unit tests of every mechanism.
!> Prints one line per failure and ends with "fortran: N passed, M failed".
program kinetostat_tests
  use test_harness, only: test_counts_t, report_counts
  use test_foundation, only: run_foundation_tests
  use test_pr3207, only: run_pr3207_tests
  use test_pr3050, only: run_pr3050_tests
  use test_sixbar, only: run_sixbar_tests
  use test_gears, only: run_gears_tests
  use test_cam, only: run_cam_tests
  use test_assur, only: run_assur_tests
  use test_io, only: run_io_tests
  implicit none
  type(test_counts_t) :: t
  call run_foundation_tests(t)
  call run_pr3207_tests(t)
  call run_pr3050_tests(t)
  call run_sixbar_tests(t)
  call run_gears_tests(t)
  call run_cam_tests(t)
  call run_assur_tests(t)
  call run_io_tests(t)
  call report_counts(t)
end program kinetostat_tests
