!> Tests of the shared layers: vectors and angles, self-check measures, LAPACK wrapper.
module test_foundation
  use kinetostat_kinds, only: wp, pi
  use kinetostat_error, only: error_t, exit_geometry
  use kinetostat_vec2, only: angle_360_deg, angle_180_deg, cross, perp, rotate, snap_noise
  use kinetostat_selfcheck, only: link_residual, power_mismatch
  use kinetostat_lapack, only: solve_dense
  use test_harness, only: test_counts_t, check_close, check_true, operator(.dot.)
  implicit none
  private
  public :: run_foundation_tests

contains

  subroutine run_foundation_tests(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: tol = 1.0e-14_wp
    real(wp) :: a(3, 3), x(3), r
    type(error_t), allocatable :: error

    ! angles: ranges, zero vector, signed zeros
    call check_close(t, "angle_360 of (-1,-1)", 225.0_wp, angle_360_deg([-1.0_wp, -1.0_wp]), tol, tol)
    call check_close(t, "angle_180 of (-1,-1)", -135.0_wp, angle_180_deg([-1.0_wp, -1.0_wp]), tol, tol)
    call check_close(t, "angle of zero vector", 0.0_wp, angle_360_deg([0.0_wp, -0.0_wp]), 0.0_wp, 0.0_wp)
    call check_close(t, "angle_180 of (-1,-0) is +180", 180.0_wp, angle_180_deg([-1.0_wp, -0.0_wp]), tol, tol)
    call check_close(t, "angle_360 of (1,-1e-300) stays below 360", 0.0_wp, &
                     angle_360_deg([1.0_wp, -1.0e-300_wp]), 0.0_wp, 1.0e-12_wp)
    call check_true(t, "angle_360 < 360", angle_360_deg([1.0_wp, -1.0e-300_wp]) < 360.0_wp, "got 360")
    call check_close(t, "cross", -2.0_wp, cross([1.0_wp, 1.0_wp], [2.0_wp, 0.0_wp]), tol, tol)
    call check_close(t, "perp", 3.0_wp, perp([3.0_wp, 4.0_wp]) .dot. [0.0_wp, 1.0_wp], tol, tol)
    call check_close(t, "rotate 90", 1.0_wp, rotate([1.0_wp, 0.0_wp], pi / 2)  .dot. [0.0_wp, 1.0_wp], tol, tol)
    call check_close(t, "snap_noise keeps", 1.0_wp, sum(snap_noise([0.6_wp, 0.4_wp], 1.0e-9_wp)), tol, tol)
    call check_close(t, "snap_noise zeroes", 0.0_wp, sum(abs(snap_noise([1.0e-13_wp, 0.0_wp], 1.0e-12_wp))), 0.0_wp, 0.0_wp)

    ! residual of a balanced lever: 2 N at x=1 up, 1 N at x=2 down, 1 N at 0 down
    r = link_residual(reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp], [2, 3]), &
                      reshape([0.0_wp, -1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, -1.0_wp], [2, 3]), [real(wp) ::])
    call check_close(t, "balanced lever residual", 0.0_wp, r, 0.0_wp, tol)
    ! the same with a missing 1 N*m couple: moment residual 1 / (2 + 2) = 0.25
    r = link_residual(reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp], [2, 3]), &
                      reshape([0.0_wp, -1.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, -1.0_wp], [2, 3]), [1.0_wp])
    call check_close(t, "unbalanced lever residual", 1.0_wp / 5.0_wp, r, tol, tol)
    call check_close(t, "power mismatch scaled by max(|q|,scale)", 0.01_wp / 1.01_wp, &
                     power_mismatch(1.01_wp, 1.0_wp, 1.0_wp), 1.0e-12_wp, 0.0_wp)

    ! LAPACK wrapper: a known solution, then a singular matrix -> geometry error
    a = reshape([4.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 3.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 2.0_wp], [3, 3])
    call solve_dense(a, matmul(a, [1.0_wp, -2.0_wp, 3.0_wp]), x, error)
    call check_true(t, "solve_dense ok", .not. allocated(error), "unexpected error")
    call check_close(t, "solve_dense x1", 1.0_wp, x(1), 1.0e-13_wp, 1.0e-13_wp)
    call check_close(t, "solve_dense x2", -2.0_wp, x(2), 1.0e-13_wp, 1.0e-13_wp)
    call check_close(t, "solve_dense x3", 3.0_wp, x(3), 1.0e-13_wp, 1.0e-13_wp)
    a(:, 3) = a(:, 1) + a(:, 2)
    call solve_dense(a, [1.0_wp, 1.0_wp, 1.0_wp], x, error)
    call check_true(t, "solve_dense singular -> error", allocated(error), "no error for a singular matrix")
    if (allocated(error)) call check_true(t, "solve_dense singular -> exit 3", error%code == exit_geometry, &
                                          "wrong exit code")
  end subroutine run_foundation_tests

end module test_foundation
