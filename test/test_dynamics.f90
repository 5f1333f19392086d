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
  use kinetostat_pr3207_deck, only: pr3207_deck_t, read_pr3207_deck, pr3207_phi1_deg
  use kinetostat_pr3207_layout, only: pr3207_solve
  use kinetostat_pr3207_dynamics, only: pr3207_source_t, pr3207_cycle
  use kinetostat_dynamics, only: reduced_t, cycle_t, motion_t, motion_at, dynamics_given, drive_at
  use kinetostat_assur, only: assur_step_t, assur_step
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck
  use kinetostat_assur_dynamics, only: assur_reduced_at
  use kinetostat_sixbar, only: sixbar_params_t, sixbar_position_t, sixbar_step_t, sixbar_position, sixbar_step, &
    sixbar_reduced
  use kinetostat_sixbar_deck, only: sixbar_deck_t, read_sixbar_deck, sixbar_phi1_deg
  use kinetostat_sixbar_layout, only: sixbar_solve
  use kinetostat_sixbar_dynamics, only: sixbar_source_t, sixbar_source, sixbar_cycle, sixbar_load_at
  use kinetostat_dynamics, only: dynamics_steady
  use kinetostat_pr3050, only: pr3050_params_t, pr3050_position_t, pr3050_position, pr3050_step, pr3050_step_t, &
    pr3050_reduced
  use kinetostat_pr3050_deck, only: pr3050_deck_t, read_pr3050_deck, pr3050_phi3_deg
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
    call test_assur_reduced(t)
    call test_sixbar_reduced(t)
    call test_pr3050_reduced(t)
    call test_sixbar_cycle(t)
  end subroutine run_dynamics_tests

  !> The T.FTN six-bar's steady cycle (data/sixbar_flywheel.nml, f5 a load table over the crank
  !> angle): delta reached = delta asked, periodicity, dT against an independent Simpson
  !> integral on 0.01 deg steps, the energy equation, M1 = M_d at every step of the force
  !> analysis with the true motion, 'given' with the flywheel found gives back delta, and a
  !> huge flywheel gives the constant-speed reactions.
  subroutine test_sixbar_cycle(t)
    type(test_counts_t), intent(inout) :: t
    type(sixbar_deck_t) :: deck, given, big
    type(sixbar_source_t) :: source
    type(cycle_t) :: cycle, cycle_given, cycle_big
    type(error_t), allocatable :: error
    type(deck_source_t) :: text
    type(motion_t) :: m0, m1, mp
    type(sixbar_step_t), allocatable :: steps(:), const(:)
    real(wp) :: phi0, phi, simpson, e_scale, worst, scale
    integer :: i, k, n
    character(len=40) :: at
    call load_deck("data/sixbar_flywheel.nml", text, error)
    if (.not. allocated(error)) call read_sixbar_deck(text, deck, error)
    call check_true(t, "read data/sixbar_flywheel.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    source = sixbar_source(deck)
    call check_close(t, "sixbar load table at a step = the step's load", deck%f5(181), &
                     sixbar_load_at(source, sixbar_phi1_deg(deck, 181) * deg_to_rad), 1.0e-12_wp, 0.0_wp)
    call check_close(t, "sixbar load table halfway between steps 181 and 182", 500.0_wp, &
                     sixbar_load_at(source, (sixbar_phi1_deg(deck, 181) + 0.5_wp) * deg_to_rad), 1.0e-9_wp, 0.0_wp)
    call sixbar_cycle(deck, source, "data/sixbar_flywheel.nml", cycle, error)
    call check_true(t, "sixbar steady cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call check_close(t, "sixbar delta reached = delta asked", 0.001_wp, cycle%delta, 1.0e-9_wp, 0.0_wp)
    call check_close(t, "sixbar (omega_max + omega_min)/2 = omega1", 100.0_wp, &
                     0.5_wp * (cycle%omega_max + cycle%omega_min), 1.0e-12_wp, 0.0_wp)
    phi0 = deck%phi_start * deg_to_rad
    m0 = motion_at(source, cycle, phi0)
    m1 = motion_at(source, cycle, phi0 + 2 * pi)
    call check_close(t, "sixbar omega(phi0) = omega(phi0 + 360)", m0%omega, m1%omega, 1.0e-12_wp, 0.0_wp)
    ! dT against composite Simpson on 0.01 deg (the table's bends at +180 and +181 deg on the grid)
    e_scale = maxval(abs(cycle%dt))
    n = 36000
    simpson = 0.0_wp
    do i = 2, n, 2
      phi = phi0 + 2 * pi * real(i, wp) / real(n, wp)
      simpson = simpson + (f(phi - 4 * pi / n) + 4 * f(phi - 2 * pi / n) + f(phi)) * (2 * pi / n) / 3
      if (mod(i, 3000) == 0) then
        write (at, '(" at +",f7.2," deg")') real(i, wp) / 100
        mp = motion_at(source, cycle, phi)
        call check_close(t, "sixbar dT vs Simpson"//trim(at), simpson, mp%dt, 0.0_wp, 1.0e-9_wp * e_scale)
        call check_close(t, "sixbar energy equation"//trim(at), 0.5_wp * (cycle%j_flywheel + m0%j) * m0%omega**2 + mp%dt, &
                         0.5_wp * (cycle%j_flywheel + mp%j) * mp%omega**2, 1.0e-12_wp, 0.0_wp)
      end if
    end do
    ! the force analysis with the true motion: M1 = M_d at every step
    call sixbar_solve("data/sixbar_flywheel.nml", deck, steps, error, source=source, cycle=cycle)
    call check_true(t, "sixbar steps with the true motion", .not. allocated(error), "error")
    if (allocated(error)) return
    worst = maxval(abs(steps%m1 - cycle%m_d))
    call check_close(t, "sixbar M1 = M_d at every step", 0.0_wp, worst, 0.0_wp, &
                     1.0e-9_wp * max(abs(cycle%m_d), maxval(abs(steps%m1_power)), 1.0_wp))
    call check_true(t, "sixbar equilibrium and power balance with the true motion", &
      maxval(steps%residual) <= 1.0e-9_wp .and. maxval(steps%mismatch) <= 1.0e-9_wp, "self-check above 1e-9")
    ! 'given' with the flywheel found gives back delta
    given = deck
    given%dyn%mode = dynamics_given
    given%dyn%j_flywheel = cycle%j_flywheel
    call sixbar_cycle(given, source, "given", cycle_given, error)
    call check_true(t, "sixbar given cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call check_close(t, "sixbar given J_fw gives back delta", 0.001_wp, cycle_given%delta, 1.0e-9_wp, 0.0_wp)
    ! a huge flywheel: the constant-speed reactions
    big = deck
    big%dyn%mode = dynamics_given
    big%dyn%j_flywheel = 1.0e12_wp
    call sixbar_cycle(big, source, "big", cycle_big, error)
    call check_true(t, "sixbar huge flywheel cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call sixbar_solve("big", big, steps, error, source=source, cycle=cycle_big)
    call sixbar_solve("big", deck, const, error)
    worst = 0.0_wp
    do k = 1, size(steps)
      scale = max(norm2(const(k)%f21), norm2(const(k)%f36), norm2(const(k)%f16), 1.0_wp)
      worst = max(worst, norm2(steps(k)%f21 - const(k)%f21) / scale, norm2(steps(k)%f32 - const(k)%f32) / scale, &
                  norm2(steps(k)%f43 - const(k)%f43) / scale, norm2(steps(k)%f36 - const(k)%f36) / scale, &
                  norm2(steps(k)%f16 - const(k)%f16) / scale, abs(steps(k)%f56 - const(k)%f56) / scale)
    end do
    call check_close(t, "sixbar huge flywheel: reactions of the constant-speed run", 0.0_wp, worst, 0.0_wp, 1.0e-6_wp)
    if (dynamics_steady < 0) return
  contains
    !> M_d + M_red at x (rad).
    real(wp) function f(x)
      real(wp), intent(in) :: x
      type(reduced_t) :: red
      red = source%at(x)
      f = cycle%m_d + red%m
    end function f
  end subroutine test_sixbar_cycle

  !> PR 3050 (data/pr3050.nml), reduced to the cylinder's stroke s: J_red = 2T at ds/dt = 1
  !> (T from central differences of the positions, divided by (ds/dphi3)^2 also from
  !> differences), dJ_red against differences of J_red over differences of s, M_red = -F2 at
  !> rest, and Lagrange's equation in s, F2 = J_red s'' + dJ_red s'^2/2 - M_red, against the
  !> force analysis with the deck's omega3, eps3 (the inertia's part too).
  subroutine test_pr3050_reduced(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: h = 1.0e-5_wp
    type(pr3050_deck_t) :: deck
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    type(pr3050_position_t) :: pm, pp, p0
    type(pr3050_step_t) :: s
    real(wp) :: red(3), rp(3), rm(3), phi, t2, ds, sdot, sddot
    character(len=32) :: at
    integer :: k
    call load_deck("data/pr3050.nml", source, error)
    if (.not. allocated(error)) call read_pr3050_deck(source, deck, error)
    call check_true(t, "read data/pr3050.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    do k = 1, deck%n
      phi = pr3050_phi3_deg(deck, k) * deg_to_rad
      write (at, '(" at phi3=",f8.2)') phi / deg_to_rad
      pm = pr3050_position(deck%p, phi - h)
      pp = pr3050_position(deck%p, phi + h)
      ds = (pp%s - pm%s) / (2 * h)
      associate (p => deck%p)
        t2 = p%m1 * sum(((pp%s1 - pm%s1) / (2 * h))**2) + p%m2 * sum(((pp%s2 - pm%s2) / (2 * h))**2) + &
             p%m3 * sum(((pp%s3 - pm%s3) / (2 * h))**2) + (p%j1 + p%j2) * ((pp%phi2 - pm%phi2) / (2 * h))**2 + p%j3
      end associate
      red = pr3050_reduced(deck%p, phi)
      call check_close(t, "pr3050 J_red (kg) vs 2T(FD) at ds/dt = 1"//trim(at), t2 / ds**2, red(1), 1.0e-8_wp, 1.0e-10_wp)
      rp = pr3050_reduced(deck%p, phi + h)
      rm = pr3050_reduced(deck%p, phi - h)
      call check_close(t, "pr3050 dJ_red (kg/m) vs FD of J_red over s"//trim(at), (rp(1) - rm(1)) / (pp%s - pm%s), &
                       red(2), 1.0e-6_wp, 1.0e-6_wp)
      s = pr3050_step(deck%p, phi, 0.0_wp, 0.0_wp)
      call check_close(t, "pr3050 M_red (N) vs -F2 (inertia off)"//trim(at), -s%f2, red(3), 1.0e-11_wp, 1.0e-9_wp)
      s = pr3050_step(deck%p, phi, deck%omega3(k), deck%eps3(k))
      p0 = pr3050_position(deck%p, phi)
      sdot = p0%ds * deck%omega3(k)
      sddot = p0%dds * deck%omega3(k)**2 + p0%ds * deck%eps3(k)
      call check_close(t, "pr3050 Lagrange in s: F2 = J_red s'' + dJ_red s'^2/2 - M_red"//trim(at), s%f2, &
                       red(1) * sddot + 0.5_wp * red(2) * sdot**2 - red(3), 1.0e-11_wp, 1.0e-9_wp)
    end do
  end subroutine test_pr3050_reduced

  !> The T.FTN six-bar (data/sixbar.nml): J_red = 2T at omega1 = 1 from finite differences of
  !> the positions, dJ_red against differences of J_red, M_red = -M1 at rest.
  subroutine test_sixbar_reduced(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: h = 1.0e-5_wp
    type(sixbar_deck_t) :: deck
    type(sixbar_params_t) :: still
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    type(sixbar_position_t) :: pm, pp
    type(sixbar_step_t) :: s
    real(wp) :: red(3), rp(3), rm(3), phi, t2
    character(len=32) :: at
    integer :: k
    call load_deck("data/sixbar.nml", source, error)
    if (.not. allocated(error)) call read_sixbar_deck(source, deck, error)
    call check_true(t, "read data/sixbar.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    still = deck%p
    still%omega1 = 0.0_wp
    do k = 2, deck%n - 1, 3
      phi = sixbar_phi1_deg(deck, k) * deg_to_rad
      write (at, '(" at phi1=",f8.2)') phi / deg_to_rad
      pm = sixbar_position(deck%p, phi - h)
      pp = sixbar_position(deck%p, phi + h)
      associate (p => deck%p)
        t2 = p%j1 + p%m2 * sum(((pp%s2 - pm%s2) / (2 * h))**2) + p%j2 * ((pp%phi2 - pm%phi2) / (2 * h))**2 + &
             p%j3 * ((pp%phi3 - pm%phi3) / (2 * h))**2 + p%m4 * sum(((pp%s4 - pm%s4) / (2 * h))**2) + &
             p%j4 * ((pp%phi4 - pm%phi4) / (2 * h))**2 + p%m5 * ((pp%h(1) - pm%h(1)) / (2 * h))**2
      end associate
      red = sixbar_reduced(deck%p, phi, 1000.0_wp)
      call check_close(t, "sixbar J_red vs 2T(FD)"//trim(at), t2, red(1), 1.0e-8_wp, 1.0e-10_wp)
      rp = sixbar_reduced(deck%p, phi + h, 1000.0_wp)
      rm = sixbar_reduced(deck%p, phi - h, 1000.0_wp)
      call check_close(t, "sixbar dJ_red vs FD of J_red"//trim(at), (rp(1) - rm(1)) / (2 * h), red(2), 1.0e-6_wp, 1.0e-9_wp)
      s = sixbar_step(still, phi, 1000.0_wp)
      call check_close(t, "sixbar M_red vs -M1 (inertia off)"//trim(at), -s%m1, red(3), 1.0e-11_wp, 1.0e-9_wp)
    end do
  end subroutine test_sixbar_reduced

  !> The generic engine's reduced quantities on the twin deck data/assur_pr3207.nml: equal to
  !> PR 3207's (an independent derivation) and M_red = -M1 of its force analysis at rest.
  subroutine test_assur_reduced(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: angles_deg(*) = [0.0_wp, 33.0_wp, 95.0_wp, 140.0_wp, 200.0_wp, 264.0_wp, 300.0_wp]
    type(assur_deck_t) :: deck
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    type(reduced_t) :: red
    type(assur_step_t) :: step
    real(wp) :: r(3), phi, f5c
    character(len=32) :: at
    integer :: i
    call load_deck("data/assur_pr3207.nml", source, error)
    if (.not. allocated(error)) call read_assur_deck(source, deck, error)
    call check_true(t, "read data/assur_pr3207.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    do i = 1, size(angles_deg)
      write (at, '(" at phi1=",f7.2)') angles_deg(i)
      phi = angles_deg(i) * deg_to_rad
      f5c = merge(3000.0_wp, 0.0_wp, angles_deg(i) >= 95.0_wp .and. angles_deg(i) <= 265.0_wp)
      red = assur_reduced_at(deck, phi)
      r = pr3207_reduced(ref, phi, f5c)
      call check_close(t, "assur J_red = pr3207 J_red"//trim(at), r(1), red%j, 1.0e-12_wp, 1.0e-14_wp)
      call check_close(t, "assur dJ_red = pr3207 dJ_red"//trim(at), r(2), red%dj, 1.0e-11_wp, 1.0e-12_wp)
      call check_close(t, "assur M_red = pr3207 M_red"//trim(at), r(3), red%m, 1.0e-12_wp, 1.0e-10_wp)
      call assur_step(deck%mech, phi, 0.0_wp, 0.0_wp, [f5c], [real(wp) ::], step, error)
      call check_true(t, "assur step at rest"//trim(at), .not. allocated(error), "error")
      call check_close(t, "assur M_red vs -M1 (inertia off)"//trim(at), -step%m1, red%m, 1.0e-11_wp, 1.0e-9_wp)
    end do
  end subroutine test_assur_reduced

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
    type(pr3207_deck_t) :: deck, free
    type(error_t), allocatable :: error
    type(deck_source_t) :: source
    type(cycle_t) :: cycle, given, big
    call load_deck("data/pr3207_flywheel.nml", source, error)
    if (.not. allocated(error)) call read_pr3207_deck(source, deck, error)
    call check_true(t, "read data/pr3207_flywheel.nml", .not. allocated(error), "deck rejected")
    if (allocated(error)) return
    call pr3207_cycle(deck, "data/pr3207_flywheel.nml", cycle, error)
    call check_true(t, "pr3207 steady cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call check_close(t, "pr3207 delta reached = delta asked", 0.04_wp, cycle%delta, 1.0e-9_wp, 0.0_wp)
    call check_close(t, "pr3207 (omega_max + omega_min)/2 = omega1", 7.5_wp, &
                     0.5_wp * (cycle%omega_max + cycle%omega_min), 1.0e-12_wp, 0.0_wp)
    call check_close(t, "pr3207 delta from the extremes", 0.04_wp, (cycle%omega_max - cycle%omega_min) / 7.5_wp, &
                     1.0e-9_wp, 0.0_wp)
    call check_cycle_laws(t, "pr3207 steady", deck, cycle)
    ! 'given' with the steady flywheel gives back delta
    free = deck
    free%dyn%mode = dynamics_given
    free%dyn%j_flywheel = cycle%j_flywheel
    call pr3207_cycle(free, "given", given, error)
    call check_true(t, "pr3207 given cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call check_close(t, "pr3207 given J_fw gives back delta", 0.04_wp, given%delta, 1.0e-9_wp, 0.0_wp)
    ! a very large flywheel: constant speed, the constant-speed reactions
    free%dyn%j_flywheel = 1.0e9_wp
    call pr3207_cycle(free, "big", big, error)
    call check_true(t, "pr3207 huge flywheel cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call check_close(t, "pr3207 huge flywheel: omega_max = omega1", 7.5_wp, big%omega_max, 1.0e-8_wp, 0.0_wp)
    call check_close(t, "pr3207 huge flywheel: omega_min = omega1", 7.5_wp, big%omega_min, 1.0e-8_wp, 0.0_wp)
    call check_constant_speed_forces(t, free, big)
    ! a free machine: no loads, no gravity
    free%p%g = 0.0_wp
    free%f5c_work = 0.0_wp
    free%dyn%j_flywheel = 2.0_wp
    call pr3207_cycle(free, "free", given, error)
    call check_true(t, "pr3207 free machine cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call check_close(t, "pr3207 free machine: M_d = 0", 0.0_wp, given%m_d, 0.0_wp, 1.0e-12_wp)
    call check_cycle_laws(t, "pr3207 free", free, given)
    call check_free_energy(t, free, given)
    call test_pr3207_drive_table(t, deck)
  end subroutine test_pr3207_cycle

  !> A driving-moment table (a motor characteristic over the crank angle, any scale) on
  !> data/pr3207_flywheel.nml: scaled so that the cycle does zero net work (its work by an
  !> independent Simpson integral = minus the loads'), its shape kept, delta reached, the
  !> cycle's laws (dT against Simpson of M_d(phi) + M_red, energy equation, M1 = M_d(phi) at
  !> every step), and a table whose work has the loads' sign is an error.
  subroutine test_pr3207_drive_table(t, base)
    type(test_counts_t), intent(inout) :: t
    type(pr3207_deck_t), intent(in) :: base
    type(pr3207_deck_t) :: deck
    type(cycle_t) :: cycle, constant
    type(error_t), allocatable :: error
    type(pr3207_source_t) :: source
    type(reduced_t) :: red
    real(wp) :: w_drive, w_loads, x, h
    integer :: i, n
    deck = base
    deck%dyn%md_phi = [0.0_wp, 90.0_wp, 180.0_wp, 270.0_wp]
    deck%dyn%md_value = [1.0_wp, 1.5_wp, 1.0_wp, 0.5_wp]
    call pr3207_cycle(deck, "table", cycle, error)
    call check_true(t, "pr3207 drive table: cycle solved", .not. allocated(error), "error")
    if (allocated(error)) return
    call pr3207_cycle(base, "constant", constant, error)
    ! Simpson on 0.01 deg over the turn (the table's points and the cut's switches on the grid)
    source%deck = deck
    n = 36000
    h = 2 * pi / n
    w_drive = 0.0_wp
    w_loads = 0.0_wp
    do i = 0, n - 2, 2
      x = h * i
      w_drive = w_drive + h / 3 * (drive_at(cycle, x) + 4 * drive_at(cycle, x + h) + drive_at(cycle, x + 2 * h))
      w_loads = w_loads + h / 3 * (m_red(x + 1.0e-9_wp) + 4 * m_red(x + h) + m_red(x + 2 * h - 1.0e-9_wp))
    end do
    call check_close(t, "pr3207 drive table: zero net work (Simpson)", -w_loads, w_drive, 1.0e-9_wp, 0.0_wp)
    call check_close(t, "pr3207 drive table: mean = the constant M_d", constant%m_d, w_drive / (2 * pi), 1.0e-9_wp, 0.0_wp)
    call check_close(t, "pr3207 drive table: shape kept (90 deg / 0 deg)", 1.5_wp, &
                     drive_at(cycle, 0.5_wp * pi) / drive_at(cycle, 0.0_wp), 1.0e-12_wp, 0.0_wp)
    call check_close(t, "pr3207 drive table: linear between points (45 deg)", 1.25_wp * cycle%drive_scale, &
                     drive_at(cycle, 0.25_wp * pi), 1.0e-12_wp, 0.0_wp)
    call check_close(t, "pr3207 drive table: periodic (315 deg)", 0.75_wp * cycle%drive_scale, &
                     drive_at(cycle, 1.75_wp * pi), 1.0e-12_wp, 0.0_wp)
    call check_close(t, "pr3207 drive table: delta reached", 0.04_wp, cycle%delta, 1.0e-9_wp, 0.0_wp)
    call check_cycle_laws(t, "pr3207 drive table", deck, cycle)
    ! a consumer's shape where the loads consume: no positive scale
    deck%dyn%md_value = -deck%dyn%md_value
    call pr3207_cycle(deck, "negative", cycle, error)
    call check_true(t, "pr3207 drive table of the loads' sign: an error", allocated(error), "no error")
    if (allocated(error)) call check_true(t, "pr3207 drive table error names md_table", &
      index(error%message, "md_table") > 0, error%message)
  contains
    real(wp) function m_red(x)
      real(wp), intent(in) :: x
      red = source%at(x)
      m_red = red%m
    end function m_red
  end subroutine test_pr3207_drive_table

  !> Laws of a solved cycle: periodicity, dT against an independent composite Simpson
  !> integral of M_d + M_red on 0.01 deg steps, the energy equation, eps = omega domega/dphi
  !> (central differences), the extremes bound omega on a 0.01 deg grid, t(360) = period, and
  !> M1 = M_d at every step of the force analysis with the true motion.
  subroutine check_cycle_laws(t, name, deck, cycle)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name
    type(pr3207_deck_t), intent(in) :: deck
    type(cycle_t), intent(in) :: cycle
    type(pr3207_source_t) :: source
    type(motion_t) :: m0, m1, mp, mm
    type(pr3207_step_t), allocatable :: steps(:)
    real(wp), parameter :: h = 1.0e-5_wp
    real(wp) :: phi, simpson, e_scale, w_hi, w_lo, worst
    integer :: i, n
    character(len=40) :: at
    source%deck = deck
    m0 = motion_at(source, cycle, 0.0_wp)
    m1 = motion_at(source, cycle, 2 * pi)
    call check_close(t, name//": omega(0) = omega(360)", m0%omega, m1%omega, 1.0e-12_wp, 0.0_wp)
    call check_close(t, name//": t(360) = period", cycle%period, m1%t, 1.0e-12_wp, 0.0_wp)
    e_scale = max(maxval(abs(cycle%dt)), 0.5_wp * (cycle%j_flywheel + maxval(cycle%j)) * cycle%omega_mean**2 * 1.0e-6_wp)
    ! Simpson on 36000 intervals, with the switches of the cutting force (95, 265 deg) on its grid
    n = 36000
    simpson = 0.0_wp
    w_hi = -huge(1.0_wp)
    w_lo = huge(1.0_wp)
    do i = 0, n
      phi = 2 * pi * real(i, wp) / real(n, wp)
      mp = motion_at(source, cycle, phi)
      w_hi = max(w_hi, mp%omega)
      w_lo = min(w_lo, mp%omega)
      if (mod(i, 3000) == 0 .and. i > 0) then
        write (at, '(" at ",f7.2," deg")') phi / deg_to_rad
        call check_close(t, name//": dT vs Simpson"//trim(at), simpson_to(i), mp%dt, 0.0_wp, 1.0e-9_wp * e_scale)
        call check_close(t, name//": energy equation"//trim(at), &
          0.5_wp * (cycle%j_flywheel + m0%j) * m0%omega**2 + mp%dt, &
          0.5_wp * (cycle%j_flywheel + mp%j) * mp%omega**2, 1.0e-12_wp, 0.0_wp)
        if (abs(phi / deg_to_rad - 95.0_wp) > 0.1_wp .and. abs(phi / deg_to_rad - 265.0_wp) > 0.1_wp .and. &
            .not. near_table_point(phi)) then
          mm = motion_at(source, cycle, phi - h)
          m1 = motion_at(source, cycle, phi + h)
          call check_close(t, name//": eps = d(omega^2/2)/dphi"//trim(at), &
            (m1%omega**2 - mm%omega**2) / (4 * h), mp%eps, 1.0e-6_wp, 1.0e-9_wp)
        end if
      end if
    end do
    call check_true(t, name//": omega_max bounds omega on a 0.01 deg grid", w_hi <= cycle%omega_max * (1 + 1.0e-14_wp), &
                    "grid max above omega_max")
    call check_true(t, name//": omega_min bounds omega on a 0.01 deg grid", w_lo >= cycle%omega_min * (1 - 1.0e-14_wp), &
                    "grid min below omega_min")
    mp = motion_at(source, cycle, cycle%phi_max)
    call check_close(t, name//": omega at phi_max", cycle%omega_max, mp%omega, 1.0e-12_wp, 0.0_wp)
    mp = motion_at(source, cycle, cycle%phi_min)
    call check_close(t, name//": omega at phi_min", cycle%omega_min, mp%omega, 1.0e-12_wp, 0.0_wp)
    ! the force analysis with the true motion: M1 = M_d at every step
    call pr3207_solve(deck, steps, cycle=cycle)
    worst = 0.0_wp
    do i = 1, size(steps)
      worst = max(worst, abs(steps(i)%m1 - drive_at(cycle, pr3207_phi1_deg(deck, i) * deg_to_rad)))
    end do
    call check_true(t, name//": M1 = M_d at every step (1e-9 of the moment scale)", &
      worst <= 1.0e-9_wp * max(abs(cycle%m_d), maxval(abs(steps%m1_power)), 1.0_wp), "worst |M1 - M_d| too large")
    call check_true(t, name//": equilibrium and power balance with the true motion", &
      maxval(steps%residual) <= 1.0e-9_wp .and. maxval(steps%mismatch) <= 1.0e-9_wp, "self-check above 1e-9")
  contains
    !> Composite Simpson integral of M_d + M_red over grid intervals 0 .. i (i even), pair by
    !> pair with the one-sided values at the pair's ends (a load switches on a grid point).
    real(wp) function simpson_to(i) result(w)
      integer, intent(in) :: i
      real(wp), parameter :: inset = 1.0e-9_wp
      real(wp) :: x0, step
      integer :: j
      step = 2 * pi / real(n, wp)
      w = 0.0_wp
      do j = 0, i - 2, 2
        x0 = step * real(j, wp)
        w = w + f(x0 + inset) + 4 * f(x0 + step) + f(x0 + 2 * step - inset)
      end do
      w = w * step / 3
    end function simpson_to

    !> M_d + M_red at x (rad).
    real(wp) function f(x)
      real(wp), intent(in) :: x
      type(reduced_t) :: red
      red = source%at(x)
      f = drive_at(cycle, x) + red%m
    end function f

    !> Whether x (rad) lies within 0.1 deg of a point of a driving-moment table (a kink of
    !> M_d: eps is continuous there, but its central difference is O(h) off).
    logical function near_table_point(x)
      real(wp), intent(in) :: x
      near_table_point = .false.
      if (allocated(cycle%drive_phi)) near_table_point = &
        any(abs(modulo(x - cycle%drive_phi + pi, 2 * pi) - pi) < 0.1_wp * deg_to_rad)
    end function near_table_point
  end subroutine check_cycle_laws

  !> A very large flywheel: the reactions of the constant-speed run (relative 1e-6 of the
  !> step's largest force).
  subroutine check_constant_speed_forces(t, deck, cycle)
    type(test_counts_t), intent(inout) :: t
    type(pr3207_deck_t), intent(in) :: deck
    type(cycle_t), intent(in) :: cycle
    type(pr3207_step_t), allocatable :: true_steps(:), const_steps(:)
    real(wp) :: worst, scale
    integer :: k
    call pr3207_solve(deck, true_steps, cycle=cycle)
    call pr3207_solve(deck, const_steps)
    worst = 0.0_wp
    do k = 1, size(true_steps)
      scale = max(norm2(const_steps(k)%f16), norm2(const_steps(k)%f21), norm2(const_steps(k)%f36), 1.0_wp)
      worst = max(worst, norm2(true_steps(k)%f16 - const_steps(k)%f16) / scale, &
                  norm2(true_steps(k)%f21 - const_steps(k)%f21) / scale, &
                  norm2(true_steps(k)%f36 - const_steps(k)%f36) / scale, &
                  norm2(true_steps(k)%f34 - const_steps(k)%f34) / scale)
    end do
    call check_close(t, "pr3207 huge flywheel: reactions of the constant-speed run", 0.0_wp, worst, 0.0_wp, 1.0e-6_wp)
  end subroutine check_constant_speed_forces

  !> A free machine (no loads, no gravity): 1/2 (J_fw + J_red) omega^2 constant, M1 = 0.
  subroutine check_free_energy(t, deck, cycle)
    type(test_counts_t), intent(inout) :: t
    type(pr3207_deck_t), intent(in) :: deck
    type(cycle_t), intent(in) :: cycle
    type(pr3207_source_t) :: source
    type(pr3207_step_t), allocatable :: steps(:)
    type(motion_t) :: mo
    real(wp) :: e0, e, scale
    integer :: k
    source%deck = deck
    mo = motion_at(source, cycle, 0.0_wp)
    e0 = 0.5_wp * (cycle%j_flywheel + mo%j) * mo%omega**2
    do k = 1, deck%n, 30
      mo = motion_at(source, cycle, pr3207_phi1_deg(deck, k) * deg_to_rad)
      e = 0.5_wp * (cycle%j_flywheel + mo%j) * mo%omega**2
      call check_close(t, "pr3207 free machine: kinetic energy constant", e0, e, 1.0e-13_wp, 0.0_wp)
    end do
    call pr3207_solve(deck, steps, cycle=cycle)
    scale = (cycle%j_flywheel + maxval(cycle%j)) * cycle%omega_mean**2
    call check_close(t, "pr3207 free machine: M1 = 0 at every step", 0.0_wp, maxval(abs(steps%m1)), 0.0_wp, &
                     1.0e-12_wp * scale)
  end subroutine check_free_energy

end module test_dynamics
