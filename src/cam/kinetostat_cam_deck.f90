!> `&cam` decks: reading, validation, and the commented template. Per-step data (theta, f2,
!> vdir, ds_dphi) are arrays with one value per cam angle, or a single value for all steps.
module kinetostat_cam_deck
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str
  use kinetostat_deck, only: begin_group, text_bytes, text_chars, &
    deck_context_t, unset_real, deck_source_t, namelist_probe_t, deck_error, is_set, &
    optional_default, count_values, deck_rules_t, rule_nonnegative, angle_steps_t, &
    cam_phi_deg => step_angle_deg
  use kinetostat_cam, only: cam_params_t
  implicit none
  private
  public :: cam_deck_t, read_cam_deck, cam_template, follower_translating, follower_flat
  public :: step_values_t, cam_phi_deg, cam_vdir, cam_x_b

  !> Follower: knife-edge or roller, pressure angle from the deck, no friction at the cam.
  integer, parameter :: follower_translating = 1
  !> Follower: flat face normal to its axis, pressure angle 0, friction at the cam.
  integer, parameter :: follower_flat = 2
  !> The followers as decks name them (index: follower_translating, follower_flat).
  character(*), parameter :: follower_names(2) = [character(len=11) :: "translating", "flat"]

  !> A per-step variable as a deck gives it: one value per step, or one for every step. The
  !> values are the namelist's read buffer, kept (spare elements past them unused), so no
  !> per-step array is stored beyond what the deck gives.
  type :: step_values_t
    !> The values as given (element 1 the default when none is given).
    real(wp), allocatable :: values(:)
    !> How many values the deck gave (0 or 1: element 1 for every step).
    integer :: given = 0
  contains
    procedure :: at => step_value_at
    procedure :: as_given => step_values_as_given
  end type step_values_t

  !> A validated `&cam` deck.
  type, extends(angle_steps_t) :: cam_deck_t
    !> follower_translating or follower_flat.
    integer :: follower = follower_translating
    !> Guide data, SI.
    type(cam_params_t) :: p
    !> Flat face: friction coefficient cam/follower.
    real(wp) :: f_cam = 0.0_wp
    !> Flat face: +1 cam turns counter-clockwise, -1 clockwise.
    real(wp) :: omega_dir = 1.0_wp
    !> The per-step values as the deck gives them (step k's value: theta%at(k)). A value
    !> this follower does not take is 0 for every step: theta of a flat face (its pressure
    !> angle is 0), ds_dphi of a translating follower.
    !> Translating: pressure angle, deg.
    type(step_values_t) :: theta
    !> Follower load, N (> 0 presses it onto the cam).
    type(step_values_t) :: f2
    !> Translating: motion +1 rise, -1 return, 0 at rest (the default +1 when the deck gives
    !> none); a flat face's motion is the sign of ds_dphi (see cam_vdir).
    type(step_values_t) :: vdir
    !> Flat face: velocity analogue ds/dphi, m/rad.
    type(step_values_t) :: ds_dphi
    !> Signed friction at the cam along +x on the follower (flat face: -omega_dir*f_cam).
    real(wp) :: mu_cam = 0.0_wp
  end type cam_deck_t

  !> Template deck, one line per entry.
  character(*), parameter :: cam_template(*) = [character(len=100) :: &
    "! kinetostat deck: cam with a translating follower in a guide (manual section 7).", &
    "! Guide ends C (near the cam) and D; contact point B an overhang l_over before C.", &
    "! Per-step values: one per cam angle (n values) or one value for every step.", &
    "&cam", &
    "  follower = 'translating'  ! 'translating' (knife/roller: theta given) or 'flat' (flat face)", &
    "  l      = 0.06     ! m, guide length C-D, > 0", &
    "  l_over = 0.04     ! m, overhang B-C along the axis, >= 0", &
    "  f      = 0.15     ! friction coefficient in the guide, >= 0", &
    "  phi_start = 0     ! deg, first cam angle (optional, default 0)", &
    "  dphi   = 30       ! deg, cam step (> 0)", &
    "  n      = 7        ! steps (optional; default 360/dphi + 1)", &
    "  theta  = 0, 12, 24, 30, 24, 12, 0   ! deg, pressure angle, |theta| < 90 (translating)", &
    "  f2     = 400      ! N, load on the follower towards the cam (> 0 keeps contact)", &
    "  vdir   = 1        ! +1 rise, -1 return, 0 at rest (translating; default +1)", &
    "  ! flat face only: f_cam = 0.1 (friction at the cam, >= 0), omega_dir = 1 (+1 CCW,", &
    "  ! -1 CW), ds_dphi = ... (m/rad, velocity analogue; its sign gives rise/return)", &
    "/"]

contains

  !> Read and validate a `&cam` deck.
  subroutine read_cam_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(cam_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    character(len=text_bytes * text_chars) :: follower
    real(wp) :: l, l_over, f, f_cam, omega_dir, phi_start, dphi
    real(wp), allocatable :: theta(:), f2(:), vdir(:), ds_dphi(:)
    !> Number of steps as given (an integer deck variable, read as a real: see require_whole).
    real(wp) :: n
    integer :: k
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    namelist /cam/ follower, l, l_over, f, f_cam, omega_dir, phi_start, dphi, n, theta, f2, vdir, ds_dphi

    call begin_group(source, "cam", ctx, error, rules)
    if (allocated(error)) return
    follower = " "
    l = unset_real; l_over = unset_real; f = unset_real; f_cam = unset_real
    omega_dir = unset_real; phi_start = unset_real; dphi = unset_real
    n = unset_real
    ! the per-step arrays: one value per step, or one for all
    call probe%per_step(source, ctx, "theta", theta, error)
    if (allocated(error)) return
    call probe%per_step(source, ctx, "f2", f2, error)
    if (allocated(error)) return
    call probe%per_step(source, ctx, "vdir", vdir, error)
    if (allocated(error)) return
    call probe%per_step(source, ctx, "ds_dphi", ds_dphi, error)
    if (allocated(error)) return

    read (source%records, nml=cam, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source)) ! on failure: find the line and the assignment
      read (probe%records, nml=cam, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    call rules%require_choice("follower", follower, follower_names, deck%follower, default=follower_translating)
    ! every missing required variable in one message
    call rules%require_all_set([character(len=6) :: "l", "l_over", "f", "dphi"], [l, l_over, f, dphi])
    ! guide
    call rules%require_positive("l", l)
    call rules%require_each(rule_nonnegative, [character(6) :: "l_over", "f"], [l_over, f])
    ! cam angles
    call rules%crank_steps(phi_start, dphi, n, deck%n)
    if (rules%failed(error)) return
    deck%p = cam_params_t(l=l, a=l_over, f=f)
    deck%phi_start = phi_start
    deck%dphi = dphi

    ! load, either follower
    call per_step(ctx, "f2", f2, deck%n, .true., 0.0_wp, deck%f2, error)
    if (allocated(error)) return

    if (deck%follower == follower_translating) then
      call rules%require_rule("f_cam", .not. is_set(f_cam), "only for follower = 'flat' "// &
        "(a knife/roller follower has no sliding friction at the cam)")
      call rules%require_rule("omega_dir", .not. is_set(omega_dir), "only for follower = 'flat'")
      call rules%require_rule("ds_dphi", .not. is_set(ds_dphi(1)), "only for follower = 'flat' "// &
        "(a translating follower takes the pressure angle theta)")
      if (rules%failed(error)) return
      call per_step(ctx, "theta", theta, deck%n, .true., 0.0_wp, deck%theta, error)
      if (allocated(error)) return
      do k = 1, deck%n
        if (.not. abs(deck%theta%at(k)) < 90.0_wp) then
          call deck_error(ctx, "theta("//int_str(k)//")", "must be in (-90, 90) deg (got "// &
            real_str(deck%theta%at(k))//")", error)
          return
        end if
      end do
      call per_step(ctx, "vdir", vdir, deck%n, .false., 1.0_wp, deck%vdir, error)
      if (allocated(error)) return
      do k = 1, deck%n
        if (cam_vdir(deck, k) /= 1.0_wp .and. cam_vdir(deck, k) /= -1.0_wp .and. cam_vdir(deck, k) /= 0.0_wp) then
          call deck_error(ctx, "vdir("//int_str(k)//")", "must be +1 (rise), -1 (return) or 0 (at rest) (got "// &
            real_str(cam_vdir(deck, k))//")", error)
          return
        end if
      end do
      deck%ds_dphi = step_values_t([0.0_wp], 0)
      deck%mu_cam = 0.0_wp
    else
      call rules%require_rule("theta", .not. is_set(theta(1)), "not for follower = 'flat' "// &
        "(its pressure angle is 0; give ds_dphi)")
      call rules%require_rule("vdir", .not. is_set(vdir(1)), "not for follower = 'flat' "// &
        "(the sign of ds_dphi gives rise or return)")
      f_cam = optional_default(f_cam, 0.0_wp)
      call rules%require_nonnegative("f_cam", f_cam)
      omega_dir = optional_default(omega_dir, 1.0_wp)
      call rules%require_set("omega_dir", omega_dir)
      call rules%require_rule("omega_dir", omega_dir == 1.0_wp .or. omega_dir == -1.0_wp, &
        "must be +1 (cam turns CCW) or -1 (CW) (got "//real_str(omega_dir)//")")
      if (rules%failed(error)) return
      call per_step(ctx, "ds_dphi", ds_dphi, deck%n, .true., 0.0_wp, deck%ds_dphi, error)
      if (allocated(error)) return
      deck%theta = step_values_t([0.0_wp], 0)
      deck%f_cam = f_cam
      deck%omega_dir = omega_dir
      deck%mu_cam = -omega_dir * f_cam
    end if
  end subroutine read_cam_deck


  !> Motion of step k: +1 rise, -1 return, 0 at rest (flat face: the sign of ds/dphi).
  pure real(wp) function cam_vdir(deck, k) result(vdir)
    !> Validated deck.
    type(cam_deck_t), intent(in) :: deck
    !> Step number, 1..n.
    integer, intent(in) :: k
    !> Flat face: velocity analogue of the step, m/rad.
    real(wp) :: ds_dphi
    if (deck%follower == follower_translating) then
      vdir = deck%vdir%at(k)
    else
      ds_dphi = deck%ds_dphi%at(k)
      vdir = sign(1.0_wp, ds_dphi)
      if (ds_dphi == 0.0_wp) vdir = 0.0_wp
    end if
  end function cam_vdir

  !> Contact offset x_B of step k, m: omega_dir*ds_dphi (a flat face; 0 for a translating
  !> follower, whose ds_dphi is 0).
  pure real(wp) function cam_x_b(deck, k) result(x_b)
    !> Validated deck.
    type(cam_deck_t), intent(in) :: deck
    !> Step number, 1..n.
    integer, intent(in) :: k
    x_b = deck%omega_dir * deck%ds_dphi%at(k)
  end function cam_x_b

  !> The value of step k.
  pure real(wp) function step_value_at(self, k) result(v)
    class(step_values_t), intent(in) :: self
    !> Step number, 1..n.
    integer, intent(in) :: k
    if (self%given <= 1) then
      v = self%values(1)
    else
      v = self%values(k)
    end if
  end function step_value_at

  !> The values as given, for the input echo: the first min(n, given) values, one at least.
  pure function step_values_as_given(self, n) result(values)
    class(step_values_t), intent(in) :: self
    !> Number of steps.
    integer, intent(in) :: n
    real(wp), allocatable :: values(:)
    values = self%values(1:max(1, min(n, self%given)))
  end function step_values_as_given

  !> A per-step array: n values, or one value for all steps; `required` or else `default`.
  !> The read buffer becomes `out`'s values as it is (moved, not copied; element 1 set to
  !> `default` when none is given).
  subroutine per_step(ctx, name, values, n, required, default, out, error)
    !> Deck and group, for messages.
    type(deck_context_t), intent(in) :: ctx
    !> Variable name.
    character(*), intent(in) :: name
    !> The namelist's read buffer (unset_real past the values given); moved into `out`.
    real(wp), allocatable, intent(inout) :: values(:)
    !> Number of steps.
    integer, intent(in) :: n
    !> Whether the deck must give it.
    logical, intent(in) :: required
    !> Value of every step when not given and not required.
    real(wp), intent(in) :: default
    !> The values as given (see above).
    type(step_values_t), intent(out) :: out
    type(error_t), allocatable, intent(out) :: error
    call count_values(ctx, name, values, out%given, error)
    if (allocated(error)) return
    if (out%given == 0) then
      if (required) then
        call deck_error(ctx, name, "missing: give one value per step ("//int_str(n)//") or one for all", error)
        return
      end if
      values(1) = default
      call move_alloc(values, out%values)
    else if (out%given == 1 .or. out%given == n) then
      call move_alloc(values, out%values)
    else
      call deck_error(ctx, name, "expected "//int_str(n)//" values (one per step) or 1 (the same for all), got "// &
        int_str(out%given), error)
    end if
  end subroutine per_step

end module kinetostat_cam_deck
