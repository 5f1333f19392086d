!> Machine dynamics tests: the reduced quantities against finite differences of the kinetic
!> energy and against the static balancing moment; the steady cycle's own laws (delta reached,
!> periodicity, energy balance, M1 = M_d at every step, 'given' gives back delta, a very large
!> flywheel gives the constant-speed forces, a free machine keeps its energy).
module test_dynamics
  use kinetostat_kinds, only: wp, deg_to_rad, pi
  use kinetostat_error, only: error_t
  use kinetostat_deck, only: deck_source_t, load_deck
  use kinetostat_pr3207, only: pr3207_params_t, pr3207_position_t, pr3207_position, pr3207_reduced, &
    pr3207_step, pr3207_step_t
  use kinetostat_pr3207_deck, only: pr3207_deck_t, read_pr3207_deck, pr3207_phi1_deg, pr3207_f5c
  use kinetostat_pr3207_layout, only: pr3207_solve
  use kinetostat_pr3207_dynamics, only: pr3207_source_t, pr3207_cycle
  use kinetostat_dynamics, only: cycle_t, motion_t, motion_at, cycle_dT, dynamics_given, dynamics_steady
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_dynamics_tests

  !> The spec's reference data.
  type(pr3207_params_t), parameter :: ref = pr3207_params_t(l_ab=0.11_wp, l_ac=0.38_wp, l_cd=0.72_wp, &
    l_cs3=0.36_wp, m1=12.0_wp, m3=22.0_wp, m5=60.0_wp, j3=1.1_wp, omega1=7.5_wp, g=9.81_wp)

contains

  subroutine run_dynamics_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_pr3207_reduced(t)
    call test_pr3207_cycle(t)
  end subroutine run_dynamics_tests

  !> Kinetic energy of PR 3207's links at crank angle phi (rad) and omega1 = 1, from the
  !> positions alone (central differences, step h).
  pure real(wp) function kinetic_fd(p, phi, h) result(t2)
    type(pr3207_params_t), intent(in) :: p
    real(wp), intent(in) :: phi, h
    type(pr3207_position_t) :: pm, pp
    real(wp) :: v_s3(2), w3, v5
    pm = pr3207_position(p, phi - h)
    pp = pr3207_position(p, phi + h)
    v_s3 = (pp%s3 - pm%s3) / (2 * h)
    w3 = (modulo(pp%phi3 - pm%phi3 + pi, 2 * pi) - pi) / (2 * h)
    v5 = (pp%y5 - pm%y5) / (2 * h)
    t2 = 0.5_wp * (p%m3 * dot_product(v_s3, v_s3) + p%j3 * w3**2 + p%m5 * v5**2)
  end function kinetic_fd

  !> J_red = 2 T at omega1 = 1 (T from finite differences of the positions); dJ_red against
  !> central differences of J_red; M_red against -M1 of a run with inertia off (omega1 = 0).
  subroutine test_pr3207_reduced(t)
    type(test_counts_t), intent(inout) :: t
    !> FD step, rad; truncation ~h^2 ~ 1e-10 relative.
    real(wp), parameter :: h = 1.0e-5_wp
    real(wp), parameter :: angles_deg(*) = [0.0_wp, 5.0_wp, 47.0_wp, 95.0_wp, 181.0_wp, 250.0_wp, 333.0_wp]
    type(pr3207_params_t) :: still
    type(pr3207_step_t) :: s
    real(wp) :: red(3), rp(3), rm(3), phi
    character(len=32) :: at
    integer :: i
    still = ref
    still%omega1 = 0.0_wp
    do i = 1, size(angles_deg)
      write (at, '(" at phi1=",f7.2)') angles_deg(i)
      phi = angles_deg(i) * deg_to_rad
      red = pr3207_reduced(ref, phi, 3000.0_wp)
      call check_close(t, "pr3207 J_red vs 2T(FD)"//trim(at), 2 * kinetic_fd(ref, phi, h), red(1), 1.0e-8_wp, 1.0e-10_wp)
      rp = pr3207_reduced(ref, phi + h, 3000.0_wp)
      rm = pr3207_reduced(ref, phi - h, 3000.0_wp)
      call check_close(t, "pr3207 dJ_red vs FD of J_red"//trim(at), (rp(1) - rm(1)) / (2 * h), red(2), &
                       1.0e-7_wp, 1.0e-9_wp)
      s = pr3207_step(still, phi, 3000.0_wp)
      call check_close(t, "pr3207 M_red vs -M1 (inertia off)"//trim(at), -s%m1, red(3), 1.0e-11_wp, 1.0e-9_wp)
    end do
  end subroutine test_pr3207_reduced

  !> The steady cycle of data/pr3207_flywheel.nml and its laws.
  subroutine test_pr3207_cycle(t)
    type(test_counts_t), intent(inout) :: t
    type(pr3207_deck_t) :: deck
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    type(cycle_t) :: cycle
    call load_deck("data/pr3207_flywheel.nml", source, error)
    if (.not. allocated(error)) call read_pr3207_deck(source, deck, error)
    call check_true(t, "read data/pr3207_flywheel.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    deck%dyn%mode = dynamics_given
    deck%dyn%j_flywheel = 0.0_wp
    call pr3207_cycle(deck, "data/pr3207_flywheel.nml", cycle, error)
    if (allocated(error)) print *, error%message
    print *, "given0", cycle%e0, cycle%delta, cycle%omega_max, cycle%phi_max, cycle%omega_min, cycle%phi_min
    deck%dyn%j_flywheel = 300.0_wp
    call pr3207_cycle(deck, "data/pr3207_flywheel.nml", cycle, error)
    if (allocated(error)) print *, error%message
    print *, "given300", cycle%e0, cycle%delta, cycle%omega_max, cycle%phi_max, cycle%omega_min, cycle%phi_min
    deck%dyn%mode = dynamics_steady
    call pr3207_cycle(deck, "data/pr3207_flywheel.nml", cycle, error)
    if (allocated(error)) print *, error%message
    print *, "m_d", cycle%m_d, "jfw", cycle%j_flywheel, cycle%j_flywheel_textbook, cycle%delta, &
      cycle%omega_max, cycle%omega_min, minval(cycle%dt), maxval(cycle%dt), minval(cycle%j), maxval(cycle%j), &
      size(cycle%node)
  end subroutine test_pr3207_cycle

end module test_dynamics
