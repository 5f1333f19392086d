!> kinetostat's Fortran test program: physics and unit tests of every mechanism.
!> Prints one line per failure and ends with "fortran: N passed, M failed"; stops with exit
!> status 1 when anything failed. With arguments, runs only the named suites
!> (`fpm test -- pr3207 cam`); an unknown name is a usage error (exit 2) listing the names.
program kinetostat_tests
  use test_harness, only: test_counts_t, report_counts
  use test_foundation, only: run_foundation_tests
  use test_pr3207, only: run_pr3207_tests
  use test_pr3050, only: run_pr3050_tests
  use test_sixbar, only: run_sixbar_tests
  use test_gears, only: run_gears_tests
  use test_cam, only: run_cam_tests
  use test_assur, only: run_assur_tests
  use test_assur_ext, only: run_assur_ext_tests
  use test_friction, only: run_friction_tests
  use test_io, only: run_io_tests
  use test_kinematics, only: run_kinematics_tests
  use test_svg, only: run_svg_tests
  use test_decimal, only: run_decimal_tests
  use test_cells, only: run_cells_tests
  use test_lapack, only: run_lapack_tests
  use test_blocks, only: run_blocks_tests
  use test_records, only: run_records_tests
  use test_linkage, only: run_linkage_tests
  use test_hostile, only: run_hostile_tests
  use test_dynamics, only: run_dynamics_tests
  use test_shaking, only: run_shaking_tests
  use test_synthesis, only: run_synthesis_tests
  use test_columns, only: run_columns_tests
  use, intrinsic :: iso_fortran_env, only: error_unit
  implicit none
  !> Suite names, in the order they run.
  character(*), parameter :: suite_names(*) = [character(len=11) :: &
    "foundation", "pr3207", "pr3050", "sixbar", "gears", "cam", "assur", "assur_ext", "friction", "io", &
    "kinematics", "svg", "decimal", "lapack", "blocks", "records", "shaking", "dynamics", "hostile", "linkage", &
    "synthesis", "columns", "cells"]
  type(test_counts_t) :: t
  logical :: selected(size(suite_names))
  integer :: i

  call select_suites(selected)
  do i = 1, size(suite_names)
    if (selected(i)) call run_suite(trim(suite_names(i)), t)
  end do
  call report_counts(t)
  if (t%failed > 0) stop 1

contains

  !> All suites without arguments, otherwise the ones named on the command line.
  subroutine select_suites(selected)
    logical, intent(out) :: selected(:)
    character(len=64) :: arg
    integer :: i, k
    if (command_argument_count() == 0) then
      selected = .true.
      return
    end if
    selected = .false.
    do i = 1, command_argument_count()
      call get_command_argument(i, arg)
      k = findloc(suite_names, arg, dim=1)
      if (k == 0) then
        write (error_unit, '(a)') "kinetostat-tests: unknown suite '"//trim(arg)//"'; suites: "//suite_list()
        stop 2
      end if
      selected(k) = .true.
    end do
  end subroutine select_suites

  !> The suite names separated by blanks.
  function suite_list() result(list)
    character(len=:), allocatable :: list
    integer :: i
    list = trim(suite_names(1))
    do i = 2, size(suite_names)
      list = list//" "//trim(suite_names(i))
    end do
  end function suite_list

  !> Run the suite called `name`.
  subroutine run_suite(name, t)
    character(*), intent(in) :: name
    type(test_counts_t), intent(inout) :: t
    select case (name)
    case ("foundation"); call run_foundation_tests(t)
    case ("hostile"); call run_hostile_tests(t)
    case ("pr3207"); call run_pr3207_tests(t)
    case ("linkage"); call run_linkage_tests(t)
    case ("synthesis"); call run_synthesis_tests(t)
    case ("dynamics"); call run_dynamics_tests(t)
    case ("pr3050"); call run_pr3050_tests(t)
    case ("sixbar"); call run_sixbar_tests(t)
    case ("gears"); call run_gears_tests(t)
    case ("cam"); call run_cam_tests(t)
    case ("assur"); call run_assur_tests(t)
    case ("assur_ext"); call run_assur_ext_tests(t)
    case ("friction"); call run_friction_tests(t)
    case ("io"); call run_io_tests(t)
    case ("kinematics"); call run_kinematics_tests(t)
    case ("svg"); call run_svg_tests(t)
    case ("decimal"); call run_decimal_tests(t)
    case ("cells"); call run_cells_tests(t)
    case ("lapack"); call run_lapack_tests(t)
    case ("blocks"); call run_blocks_tests(t)
    case ("records"); call run_records_tests(t)
    case ("shaking"); call run_shaking_tests(t)
    case ("columns"); call run_columns_tests(t)
    case default; error stop "run_suite: no suite '"//name//"'"
    end select
  end subroutine run_suite

end program kinetostat_tests
