!> Tests of friction in the pairs of the generic engine: a crank with only a journal
!> (M1 = M_load + f*r*|F| by hand), a slider pushed along its guide in statics (f*N, and the
!> two-contact model f*(|N1| + |N2|) by hand), the friction slider-crank deck (self-check at
!> every step, P_loss >= 0, M1 - M1_0 with the sign of the motion, efficiency of the working
!> stroke in (0, 1), cycle efficiency 0 by energy conservation), zero coefficients = frictionless.
module test_friction
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_vec2, only: magnitude
  use kinetostat_assur, only: assur_step_t, pair_index, crank_pin_index
  use kinetostat_assur_friction, only: friction_step_t
  use kinetostat_assur_deck, only: assur_deck_t, read_assur_deck, assur_phi1_deg, assur_omega1, assur_load_value
  use kinetostat_deck, only: deck_source_t, load_deck, deck_source_from_text
  use kinetostat_assur_layout, only: assur_solve, friction_work
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_friction_tests

  character(*), parameter :: lf = achar(10)
  !> Self-check limit of the issue, relative.
  real(wp), parameter :: selfcheck_limit = 1.0e-9_wp

contains

  subroutine run_friction_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_crank_journal(t)
    call test_slider_statics(t)
    call test_friction_slider_crank(t)
    call test_zero_coefficients(t)
    call test_actuator_friction(t)
  end subroutine run_friction_tests

  !> Read a deck from text (or a file when `path` is given) and solve it with friction.
  subroutine solve_text(t, name, text, deck, steps, fsteps, ok)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name, text
    type(assur_deck_t), intent(out) :: deck
    type(assur_step_t), allocatable, intent(out) :: steps(:)
    type(friction_step_t), allocatable, intent(out) :: fsteps(:)
    logical, intent(out) :: ok
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    if (index(text, "&assur") > 0) then
      call deck_source_from_text(name, text, source)
    else
      call load_deck(text, source, error)
    end if
    if (.not. allocated(error)) call read_assur_deck(source, deck, error)
    if (.not. allocated(error)) call assur_solve(name, deck, steps, error, fsteps)
    ok = .not. allocated(error)
    if (ok) then
      call check_true(t, name//": solved", .true., "")
    else
      call check_true(t, name//": solved", .false., error%message)
    end if
  end subroutine solve_text

  !> A crank (2 kg, centre on the pivot) loaded by 100 N at its pin B (l = 0.1 m), normal to
  !> the crank (CCW): M_load = -P*l = -10 N*m balances it without friction. A massless, unloaded
  !> dyad carries nothing, so the pivot reaction is F10 = -(P e(phi + 90 deg) + m g), and
  !> |F10|^2 = P^2 + (m g)^2 - 2 P m g cos(phi). With the journal at A (f = 0.1, r = 0.02 m):
  !> M1 = M_load + s f r |F10| (s = sign of omega1), P_loss = f r |F10| |omega1|.
  subroutine test_crank_journal(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: p = 100.0_wp, l = 0.1_wp, m = 2.0_wp, g = 9.81_wp, f = 0.1_wp, r = 0.02_wp
    real(wp), parameter :: rtol = 1.0e-12_wp
    character(*), parameter :: deck_a = "&assur" // lf // &
      " crank_m = 2, crank_f = 0.1, crank_r = 0.02, g = 9.81, phi_start = 0, dphi = 30" // lf // &
      " dyad(1)%kind = 2, dyad(1)%link2 = 2, dyad(1)%link3 = 3, dyad(1)%on2 = 1, dyad(1)%at2 = 0.1, 0" // lf // &
      " dyad(1)%on3 = 0, dyad(1)%at3 = 0, 0, dyad(1)%angle3 = 0, dyad(1)%l2 = 0.3" // lf // &
      " force(1)%link = 1, force(1)%at = 0.1, 0, force(1)%angle = 90, force(1)%follow = .true.," // &
      " force(1)%value = 100" // lf
    type(assur_deck_t) :: deck
    type(assur_step_t), allocatable :: steps(:)
    type(friction_step_t), allocatable :: fsteps(:)
    real(wp) :: omega, fa, phi
    integer :: k, run
    logical :: ok
    character(len=64) :: at
    allocate (steps(0), fsteps(0)) ! defined before the calls (gcc's -Wmaybe-uninitialized)
    do run = 1, 2
      omega = merge(10.0_wp, -10.0_wp, run == 1)
      call solve_text(t, "crank journal", deck_a//merge(" omega1 =  10", " omega1 = -10", run == 1)//lf//"/", &
                      deck, steps, fsteps, ok)
      if (.not. ok) return
      do k = 1, size(steps)
        phi = steps(k)%phi1
        write (at, '(" (omega1 = ",f6.1,", phi1 = ",f6.1," deg)")') omega, assur_phi1_deg(deck, k)
        fa = sqrt(p**2 + (m * g)**2 - 2.0_wp * p * m * g * cos(phi))
        call check_close(t, "journal |F10| by hand"//trim(at), fa, magnitude(steps(k)%f(:, crank_pin_index(1))), &
                         rtol, 0.0_wp)
        call check_close(t, "journal M1 = M_load + s f r |F| by hand"//trim(at), -p * l + sign(f * r * fa, omega), &
                         steps(k)%m1, rtol, rtol * p * l)
        call check_close(t, "journal M1_0 = M_load"//trim(at), -p * l, fsteps(k)%driver_frictionless, rtol, 0.0_wp)
        call check_close(t, "journal P_loss = f r |F| |omega1|"//trim(at), f * r * fa * abs(omega), fsteps(k)%p_loss, &
                         rtol, 0.0_wp)
        call check_true(t, "journal self-check <= 1e-9"//trim(at), steps(k)%residual <= selfcheck_limit .and. &
                        steps(k)%mismatch <= selfcheck_limit, "residual/mismatch too large")
      end do
    end do
  end subroutine test_crank_journal

  !> Statics (omega1 = 0) of a slider of 5 kg on a horizontal guide, pulled by a horizontal
  !> massless rod (crank at 90 deg, pin B = (0, 0.1) at the guide's height, C = (0.3, 0.1)).
  !> Impending motion phi1 increasing moves B and the slider along -x; the guide's friction
  !> f N with N = m g resists, the rod carries f N, and M1 = f N * 0.1 m (frictionless: 0).
  !> With the slider's centre of mass 0.05 m ahead of C and a block of 0.04 m, the two-contact
  !> model gives f (|N1| + |N2|) = f max(N, 2|M|/c) with |M| = 0.05 m g: f * 2.5 m g.
  subroutine test_slider_statics(t)
    type(test_counts_t), intent(inout) :: t
    real(wp), parameter :: m = 5.0_wp, g = 9.81_wp, f = 0.2_wp, h = 0.1_wp, rtol = 1.0e-12_wp
    character(*), parameter :: base = "&assur" // lf // &
      " omega1 = 0, g = 9.81, phi_start = 90, dphi = 10, n = 1" // lf // &
      " dyad(1)%kind = 2, dyad(1)%link2 = 2, dyad(1)%link3 = 3, dyad(1)%on2 = 1, dyad(1)%at2 = 0.1, 0" // lf // &
      " dyad(1)%on3 = 0, dyad(1)%at3 = 0, 0.1, dyad(1)%angle3 = 0, dyad(1)%l2 = 0.3, dyad(1)%m3 = 5" // lf // &
      " dyad(1)%f3 = 0.2" // lf
    type(assur_deck_t) :: deck
    type(assur_step_t), allocatable :: steps(:)
    type(friction_step_t), allocatable :: fsteps(:)
    real(wp) :: n, q
    logical :: ok
    integer :: ip
    allocate (steps(0), fsteps(0)) ! defined before the calls (gcc's -Wmaybe-uninitialized)
    ip = pair_index(1, 3)
    n = m * g
    call solve_text(t, "slider statics", base//"/", deck, steps, fsteps, ok)
    if (ok) then
      call check_close(t, "slider statics N = m g", n, steps(1)%n(ip), rtol, 0.0_wp)
      call check_close(t, "slider statics friction = f N", f * n, fsteps(1)%effort(ip), rtol, 0.0_wp)
      call check_close(t, "slider statics rod force = f N", f * n, magnitude(steps(1)%f(:, pair_index(1, 2))), &
                       rtol, 0.0_wp)
      call check_close(t, "slider statics M1 = f N h", f * n * h, steps(1)%m1, rtol, 0.0_wp)
      call check_close(t, "slider statics M1_0 = 0", 0.0_wp, fsteps(1)%driver_frictionless, 0.0_wp, 1.0e-12_wp * n * h)
      call check_close(t, "slider statics P_loss = 0 at rest", 0.0_wp, fsteps(1)%p_loss, 0.0_wp, 0.0_wp)
      call check_true(t, "slider statics self-check <= 1e-9", steps(1)%residual <= selfcheck_limit .and. &
                      steps(1)%mismatch <= selfcheck_limit, "residual/mismatch too large")
    end if
    q = f * max(n, 2.0_wp * 0.05_wp * n / 0.04_wp)
    call solve_text(t, "slider two-contact", base//" dyad(1)%s3 = 0.05, 0, dyad(1)%block3 = 0.04, "// &
                    "dyad(1)%guide3 = 1"//lf//"/", deck, steps, fsteps, ok)
    if (ok) then
      call check_close(t, "two-contact |M| = 0.05 m g", 0.05_wp * n, abs(steps(1)%m(ip)), rtol, 0.0_wp)
      call check_close(t, "two-contact friction = f (|N1| + |N2|)", q, fsteps(1)%effort(ip), rtol, 0.0_wp)
      call check_close(t, "two-contact M1 = f (|N1| + |N2|) h", q * h, steps(1)%m1, rtol, 0.0_wp)
    end if
  end subroutine test_slider_statics

  !> data/friction_slider_crank.nml: self-check <= 1e-9, P_loss >= 0 and M1 - M1_0 > 0 (omega1
  !> > 0) at every step; M1_0 equals the run of the same deck without friction; the efficiency
  !> of the working stroke (180..360 deg, the slider moving against the 500 N) lies in (0, 1);
  !> over the whole turn every load is conservative (constant force, gravity, inertia at
  !> constant omega1), so A_loss = A_driver and the cycle efficiency is 0.
  subroutine test_friction_slider_crank(t)
    type(test_counts_t), intent(inout) :: t
    character(*), parameter :: path = "data/friction_slider_crank.nml"
    type(assur_deck_t) :: deck, plain
    type(assur_step_t), allocatable :: steps(:), steps0(:)
    type(friction_step_t), allocatable :: fsteps(:)
    type(error_t), allocatable :: error
    real(wp) :: a_driver, a_loss, eta
    character(len=120) :: detail
    integer :: k
    logical :: ok
    allocate (steps(0), steps0(0), fsteps(0)) ! defined before the calls (gcc's -Wmaybe-uninitialized)
    call solve_text(t, "friction slider-crank", path, deck, steps, fsteps, ok)
    if (.not. ok) return
    call check_true(t, "friction slider-crank has 37 steps", size(steps) == 37, "wrong step count")
    plain = deck
    plain%friction%f = 0.0_wp
    plain%friction_on = .false.
    call assur_solve(path, plain, steps0, error)
    call check_true(t, "friction slider-crank without friction solved", .not. allocated(error), "error")
    if (allocated(error)) return
    do k = 1, size(steps)
      write (detail, '("phi1 = ",f6.1," deg: residual ",es9.2,", mismatch ",es9.2,", P_loss ",es10.3, &
        &", M1 - M1_0 ",es10.3)') assur_phi1_deg(deck, k), steps(k)%residual, steps(k)%mismatch, fsteps(k)%p_loss, &
        steps(k)%m1 - fsteps(k)%driver_frictionless
      call check_true(t, "friction slider-crank residual <= 1e-9", steps(k)%residual <= selfcheck_limit, detail)
      call check_true(t, "friction slider-crank power balance <= 1e-9", steps(k)%mismatch <= selfcheck_limit, detail)
      call check_true(t, "friction slider-crank P_loss >= 0", fsteps(k)%p_loss >= 0.0_wp .and. &
                      all(fsteps(k)%loss >= 0.0_wp), detail)
      call check_true(t, "friction slider-crank M1 - M1_0 has the sign of omega1 (> 0)", &
                      steps(k)%m1 - fsteps(k)%driver_frictionless > 0.0_wp, detail)
      call check_close(t, "friction slider-crank M1_0 = frictionless run", steps0(k)%m1, fsteps(k)%driver_frictionless, &
                       1.0e-12_wp, 1.0e-12_wp)
      call check_close(t, "friction slider-crank P_loss = sum of the pairs", sum(fsteps(k)%loss), fsteps(k)%p_loss, &
                       1.0e-14_wp, 0.0_wp)
    end do
    call friction_work(deck, steps, fsteps, a_driver, a_loss)
    write (detail, '("A_driver ",es22.15," J, A_loss ",es22.15," J")') a_driver, a_loss
    call check_true(t, "friction slider-crank cycle: A_driver > 0", a_driver > 0.0_wp, detail)
    call check_close(t, "friction slider-crank cycle: A_loss = A_driver (conservative loads)", a_driver, a_loss, &
                     1.0e-9_wp, 0.0_wp)
    ! the working stroke: steps 19..37 (180..360 deg: the slider moves from the inner dead centre
    ! along +x against the 500 N; from 0 to 180 deg the force drives the slider)
    call friction_work(deck, steps(19:37), fsteps(19:37), a_driver, a_loss)
    eta = 1.0_wp - a_loss / a_driver
    write (detail, '("A_driver ",es12.5," J, A_loss ",es12.5," J, eta ",f8.5)') a_driver, a_loss, eta
    call check_true(t, "friction slider-crank working stroke: eta in (0, 1)", a_driver > 0.0_wp .and. &
                    eta > 0.0_wp .and. eta < 1.0_wp, detail)
  end subroutine test_friction_slider_crank

  !> Coefficients given as 0 (and radii, lengths) leave friction off: the same steps as the
  !> plain deck.
  subroutine test_zero_coefficients(t)
    type(test_counts_t), intent(inout) :: t
    character(*), parameter :: base = "&assur" // lf // &
      " crank_m = 2, omega1 = 30, g = 9.81, phi_start = 0, dphi = 45" // lf // &
      " dyad(1)%kind = 2, dyad(1)%link2 = 2, dyad(1)%link3 = 3, dyad(1)%on2 = 1, dyad(1)%at2 = 0.1, 0" // lf // &
      " dyad(1)%on3 = 0, dyad(1)%at3 = 0, 0.02, dyad(1)%angle3 = 0, dyad(1)%l2 = 0.3, dyad(1)%m2 = 1, dyad(1)%m3 = 3" &
      // lf // " force(1)%link = 3, force(1)%angle = 180, force(1)%value = 200" // lf
    type(assur_deck_t) :: deck, deck0
    type(assur_step_t), allocatable :: steps(:), steps0(:)
    type(friction_step_t), allocatable :: fsteps(:)
    logical :: ok, same
    integer :: k
    allocate (steps(0), steps0(0), fsteps(0)) ! defined before the calls (gcc's -Wmaybe-uninitialized)
    call solve_text(t, "zero friction", base//" crank_f = 0, crank_r = 0.01, dyad(1)%f2 = 0, dyad(1)%r2 = 0.01,"// &
      " dyad(1)%f23 = 0, dyad(1)%f3 = 0, dyad(1)%guide3 = 0.2, dyad(1)%block3 = 0.05"//lf//"/", deck, steps, fsteps, ok)
    if (.not. ok) return
    call check_true(t, "zero friction: friction off", .not. deck%friction_on .and. size(fsteps) == 0, "friction on")
    call solve_text(t, "no friction", base//"/", deck0, steps0, fsteps, ok)
    if (.not. ok) return
    same = size(steps) == size(steps0)
    do k = 1, min(size(steps), size(steps0))
      same = same .and. all(steps(k)%f == steps0(k)%f) .and. steps(k)%m1 == steps0(k)%m1 .and. &
             all(steps(k)%n == steps0(k)%n) .and. all(steps(k)%m == steps0(k)%m)
    end do
    call check_true(t, "zero friction: every reaction and M1 equal (bit for bit)", same, "differ")
  end subroutine test_zero_coefficients

  !> data/assur_pr3050_friction.nml (a hydraulic cylinder drives, friction in its own pair too):
  !> self-check <= 1e-9, P_loss >= 0 at every step; F_drive_0 = F_drive of the frictionless
  !> data/assur_pr3050.nml; where the rocker moves, friction raises the driver's power:
  !> (F_drive - F_drive_0) * stroke speed > 0.
  subroutine test_actuator_friction(t)
    type(test_counts_t), intent(inout) :: t
    type(assur_deck_t) :: deck, plain
    type(assur_step_t), allocatable :: steps(:), steps0(:)
    type(friction_step_t), allocatable :: fsteps(:), none(:)
    character(len=200) :: detail
    integer :: k
    logical :: ok
    allocate (steps(0), steps0(0), fsteps(0), none(0)) ! defined before the calls (gcc's -Wmaybe-uninitialized)
    call solve_text(t, "actuator friction", "data/assur_pr3050_friction.nml", deck, steps, fsteps, ok)
    if (.not. ok) return
    call solve_text(t, "actuator without friction", "data/assur_pr3050.nml", plain, steps0, none, ok)
    if (.not. ok) return
    call check_true(t, "actuator friction: same steps", size(steps) == size(steps0) .and. size(steps) == 10, &
                    "step counts differ")
    if (size(steps) /= size(steps0)) return
    do k = 1, size(steps)
      write (detail, '("phi1 = ",f6.2," deg: residual ",es9.2,", mismatch ",es9.2,", F_drive ",es12.5,", F_drive_0 ",&
        &es12.5,", stroke_v ",es10.3)') assur_phi1_deg(deck, k), steps(k)%residual, steps(k)%mismatch, steps(k)%f_drive, &
        fsteps(k)%driver_frictionless, steps(k)%stroke_v
      call check_true(t, "actuator friction residual <= 1e-9", steps(k)%residual <= selfcheck_limit, detail)
      call check_true(t, "actuator friction F_drive power balance <= 1e-9", steps(k)%mismatch <= selfcheck_limit, detail)
      call check_true(t, "actuator friction P_loss >= 0", fsteps(k)%p_loss >= 0.0_wp, detail)
      call check_close(t, "actuator F_drive_0 = frictionless deck", steps0(k)%f_drive, fsteps(k)%driver_frictionless, &
                       1.0e-12_wp, 0.0_wp)
      if (assur_omega1(deck, k) /= 0.0_wp) call check_true(t, "actuator friction raises the driver's power", &
        (steps(k)%f_drive - fsteps(k)%driver_frictionless) * steps(k)%stroke_v > 0.0_wp, detail)
    end do
  end subroutine test_actuator_friction

end module test_friction
