!> kinetostat: kinetostatic force analysis of planar mechanisms (see README.md).
program kinetostat
  use kinetostat_cli, only: run_cli
  implicit none
  integer :: exit_code
  call run_cli(exit_code)
  if (exit_code /= 0) stop exit_code, quiet=.true.
end program kinetostat
