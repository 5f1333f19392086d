!> Tests of the shared layers: vectors and angles, self-check measures, LAPACK wrapper.
module test_foundation
  use kinetostat_kinds, only: wp, pi
  use kinetostat_error, only: error_t, exit_geometry
  use kinetostat_vec2, only: angle_360_deg, angle_180_deg, cross, perp, rotate, snap_noise
  use kinetostat_selfcheck, only: link_residual, power_mismatch, link_balance_t, balance_add_force, &
    equilibrium_residual
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
    type(link_balance_t) :: links(3)

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

    ! shared floor rule: link 1 a short loaded lever (1000 N, arms 1 mm: sum |M_i| = 4 N*m);
    ! link 2 a two-force link whose moments are roundoff (1e-13 N*m against 1000 N * 1 m): its
    ! own moment ratio is 1; judged against 1e-6 of the step's largest sum |r|*|F| (1000 N*m)
    ! it is 1e-10 (against 1e-6 of the largest sum |M_i|, 4 N*m, it would be 2.5e-8, as
    ! pr3050 with g = 0 showed)
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [0.0_wp, 1000.0_wp])
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [1.0e-3_wp, 0.0_wp], [0.0_wp, -2000.0_wp])
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [2.0e-3_wp, 0.0_wp], [0.0_wp, 1000.0_wp])
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [1000.0_wp, 0.0_wp])
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [1.0_wp, 1.0e-16_wp], [-1000.0_wp, 0.0_wp])
    call check_close(t, "two-force link: |sum M| / sum |M_i| is 1 (roundoff scale)", 1.0_wp, &
                     abs(links(2)%sum_m) / links(2)%scale_m, 1.0e-12_wp, 0.0_wp)
    r = equilibrium_residual(links(1:2))
    call check_true(t, "two-force link in its step: residual <= 1e-9", r <= 1.0e-9_wp, &
                    "residual "//trim(real_text(r))//", expected <= 1e-9")
    ! the check can still fail: a wrong reaction (999 N instead of 1000 N) on link 2 ...
    links(2) = link_balance_t()
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [1000.0_wp, 0.0_wp])
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp], [-999.0_wp, 0.0_wp])
    call check_close(t, "wrong reaction on a loaded link: residual 1/1999", 1.0_wp / 1999.0_wp, &
                     equilibrium_residual(links(1:2)), 1.0e-12_wp, 0.0_wp)
    ! ... and a 1 N force left unbalanced on an otherwise unloaded link (above the floor)
    call balance_add_force(links(3), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp])
    call check_close(t, "unbalanced 1 N on an unloaded link: residual 1", 1.0_wp, &
                     equilibrium_residual(links), 1.0e-12_wp, 0.0_wp)

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

  !> A real in es10.3 for messages.
  pure function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=10) :: text
    write (text, '(es10.3)') x
  end function real_text

end module test_foundation
