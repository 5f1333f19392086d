!> `&gears` decks: reading, validation, and the commented template. One group lists the
!> stages as arrays indexed by stage (stage(i), z1(i), ...); `layout` says whether the
!> stages are separate pairs or a reducer in series.
module kinetostat_gears_deck
  use kinetostat_kinds, only: wp, deg_to_rad, pi
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, int_str, number_str, lower
  use kinetostat_deck, only: &
    begin_group, text_bytes, text_chars, deck_context_t, unset_real, &
    deck_source_t, namelist_probe_t, is_set, deck_rules_t
  use kinetostat_gears, only: gear_stage_t, gear_helical, gear_bevel, gear_planetary, gear_kind_names
  implicit none
  private
  public :: gears_deck_t, read_gears_deck, gears_template, max_stages
  public :: layout_separate, layout_series, layout_names

  !> Largest number of stages in one deck.
  integer, parameter :: max_stages = 20
  !> Layout: independent stages, each with its own input torque.
  integer, parameter :: layout_separate = 1
  !> Layout: parallel-shaft stages in series (reducer, manual fig. 18).
  integer, parameter :: layout_series = 2
  !> Layout names as written in decks.
  character(*), parameter :: layout_names(2) = [character(len=8) :: "separate", "series"]
  !> The group's arrays, one value per stage (max_stages each).
  character(*), parameter :: stage_arrays(*) = [character(len=9) :: "stage", "m1", "z1", "z2", "m", "dw1", &
    "alpha_w", "beta", "gamma", "z3", "k", "alpha_w23"]
  !> Largest number of teeth accepted (keeps z1 + 2*z2 and the ratios far from overflow).
  integer, parameter :: max_teeth = 100000
  !> Default operating pressure angle, deg (standard basic rack).
  real(wp), parameter :: alpha_default = 20.0_wp

  !> A validated `&gears` deck (angles in the stages in rad, lengths in m).
  type :: gears_deck_t
    !> layout_separate or layout_series.
    integer :: layout = layout_separate
    !> Number of stages.
    integer :: n = 0
    !> Stage geometry, SI.
    type(gear_stage_t), allocatable :: st(:)
    !> Input torque of each stage, N*m (series: stage 1 only, the rest 0).
    real(wp), allocatable :: m1(:)
    !> Module of each stage as given, mm (0 when dw1 was given instead).
    real(wp), allocatable :: module_mm(:)
  end type gears_deck_t

  !> Template deck, one line per entry.
  character(*), parameter :: gears_template(*) = [character(len=100) :: &
    "! kinetostat deck: gear meshes (manual section 6). One &gears group; every per-stage", &
    "! variable is an array indexed by stage: stage(1), stage(2), ... (no gaps).", &
    "! Friction-free, uniform rotation. Torques N*m (CCW +), module/diameters mm, angles deg.", &
    "&gears", &
    "  layout  = 'separate'   ! 'separate' (each stage its own m1) or 'series' (reducer: gear 2", &
    "                         ! of stage i and gear 1 of stage i+1 share a shaft; m1(1) only)", &
    "  stage   = 'spur', 'helical', 'bevel', 'planetary'   ! kind of each stage", &
    "  m1      = 100, 100, 100, 100   ! N*m, torque on gear 1 (planetary: the sun) from its shaft", &
    "  z1      = 20, 20, 20, 24       ! teeth of gear 1 (planetary: sun), >= 1", &
    "  z2      = 40, 40, 40, 24       ! teeth of gear 2 (planetary: one satellite), >= 1", &
    "  m       = 4, 4, 4, 3           ! mm, module (bevel: mean-section module); or give dw1", &
    "  ! dw1   = 80, 80, 80, 72       ! mm, pitch diameter of gear 1 (bevel: d_m1); default z1*m", &
    "  alpha_w = 20, 20, 20, 20       ! deg, operating pressure angle, in (0, 45); default 20", &
    "  beta    = 0, 15, 0, 0          ! deg, helix angle (helical only), |beta| < 45; default 0", &
    "  gamma   = 0, 0, 0, 90          ! deg, direction O1->O2 (planetary: to satellite 1); def. 0", &
    "  z3      = 0, 0, 0, 72          ! planetary: ring teeth, = z1 + 2*z2 (others: leave 0)", &
    "  k       = 0, 0, 0, 3           ! planetary: number of satellites >= 1 (others: leave 0)", &
    "  ! alpha_w23 = 0, 0, 0, 20      ! deg, planetary: satellite-ring mesh; default alpha_w", &
    "/"]

contains

  !> Read and validate a `&gears` deck.
  subroutine read_gears_deck(source, deck, error)
    !> The deck, read into memory (see load_deck).
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(gears_deck_t), intent(out) :: deck
    !> Input error naming file, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    character(len=text_bytes * text_chars) :: layout, stage(max_stages)
    real(wp), dimension(max_stages) :: m1, m, dw1, alpha_w, alpha_w23, beta, gamma
    !> Teeth and satellite counts: integer deck variables, read as reals (see require_whole).
    real(wp), dimension(max_stages) :: z1, z2, z3, k
    integer :: i, n, kind, iz1, iz2, iz3, ik
    character(len=:), allocatable :: at
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    namelist /gears/ layout, stage, m1, z1, z2, m, dw1, alpha_w, beta, gamma, z3, k, alpha_w23

    call begin_group(source, "gears", ctx, error, rules)
    if (allocated(error)) return
    layout = " "
    stage = " "
    m1 = unset_real; m = unset_real; dw1 = unset_real; alpha_w = unset_real
    alpha_w23 = unset_real; beta = unset_real; gamma = unset_real
    z1 = unset_real; z2 = unset_real; z3 = unset_real; k = unset_real

    ! every variable of the group is an array of one value per stage
    call probe%limit(stage_arrays, max_stages, "stages")
    read (source%records, nml=gears, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source)) ! on failure: find the line and the assignment
      read (probe%records, nml=gears, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    call rules%require_choice("layout", layout, layout_names, deck%layout, default=layout_separate)
    ! number of stages: the leading non-blank stage entries, no gaps
    call rules%count_texts("stage", stage, "give stage = 'spur' | 'helical' | 'bevel' | 'planetary' for each stage", n)
    if (rules%failed(error)) return
    ! nothing may be given for a stage that does not exist
    call no_extra_real(rules, "m1", m1, n)
    call no_extra_real(rules, "m", m, n)
    call no_extra_real(rules, "dw1", dw1, n)
    call no_extra_real(rules, "alpha_w", alpha_w, n)
    call no_extra_real(rules, "alpha_w23", alpha_w23, n)
    call no_extra_real(rules, "beta", beta, n)
    call no_extra_real(rules, "gamma", gamma, n)
    call no_extra_real(rules, "z1", z1, n)
    call no_extra_real(rules, "z2", z2, n)
    call no_extra_real(rules, "z3", z3, n)
    call no_extra_real(rules, "k", k, n)

    ! two or more required values missing: name them all in one message (one missing value
    ! gets its own message from the checks of its stage below)
    call require_all_stages(rules, deck%layout == layout_series, stage(1:n), m1, z1, z2, z3, k, m, dw1)
    if (rules%failed(error)) return

    deck%n = n
    allocate (deck%st(n), deck%m1(n), deck%module_mm(n))
    deck%m1 = 0.0_wp
    deck%module_mm = 0.0_wp
    do i = 1, n
      at = "("//int_str(i)//")"
      call rules%require_choice("stage"//at, stage(i), gear_kind_names, kind)
      if (rules%failed(error)) return
      deck%st(i)%kind = kind
      call rules%require_rule("stage"//at, deck%layout /= layout_series .or. (kind /= gear_bevel .and. &
        kind /= gear_planetary), "'"//trim(gear_kind_names(kind))//"' cannot be a stage of "// &
        "layout 'series' (parallel-shaft spur/helical stages only)")

      ! input torque
      if (deck%layout == layout_series .and. i > 1) then
        call rules%require_rule("m1"//at, .not. is_set(m1(i)), "not allowed in layout 'series': "// &
          "the torque of stage "//int_str(i)//" comes from stage "//int_str(i - 1))
      else
        call rules%require_set("m1"//at, m1(i))
        deck%m1(i) = m1(i)
      end if

      ! teeth
      call require_teeth(rules, "z1"//at, z1(i), iz1)
      call require_teeth(rules, "z2"//at, z2(i), iz2)
      deck%st(i)%z1 = iz1
      deck%st(i)%z2 = iz2

      ! size: module or pitch diameter of gear 1
      if (is_set(dw1(i))) then
        call rules%require_positive("dw1"//at, dw1(i))
        call rules%require_rule("m"//at, .not. is_set(m(i)), "give either m or dw1 for a stage, not both")
        deck%st(i)%dw1 = dw1(i) * 1.0e-3_wp
      else
        call rules%require_rule("m"//at, is_set(m(i)), "missing: give the module m (mm) or the pitch diameter "// &
          "dw1 (mm)")
        call rules%require_positive("m"//at, m(i))
        deck%module_mm(i) = m(i)
        deck%st(i)%dw1 = real(iz1, wp) * m(i) * 1.0e-3_wp
      end if

      ! angles
      call pressure_angle(rules, "alpha_w"//at, alpha_w(i), alpha_default, deck%st(i)%alpha_w)
      if (is_set(beta(i))) then
        call rules%require_set("beta"//at, beta(i))
        call rules%require_rule("beta"//at, kind == gear_helical .or. beta(i) == 0.0_wp, &
          "only for a 'helical' stage (stage "//int_str(i)//" is '"//trim(gear_kind_names(kind))// &
          "'): leave it 0 or unset")
        call rules%require_rule("beta"//at, abs(beta(i)) < 45.0_wp, "must be in (-45, 45) deg (got "// &
          real_str(beta(i))//")")
        deck%st(i)%beta = beta(i) * deg_to_rad
      end if
      if (is_set(gamma(i))) then
        call rules%require_set("gamma"//at, gamma(i))
        deck%st(i)%gamma = gamma(i) * deg_to_rad
      end if
      if (kind == gear_bevel) deck%st(i)%delta1 = atan2(real(iz1, wp), real(iz2, wp))

      ! planetary data, only for planetary stages (0 = "not used" is accepted elsewhere)
      if (kind == gear_planetary) then
        call require_teeth(rules, "z3"//at, z3(i), iz3)
        call rules%require_rule("z3"//at, iz3 == iz1 + 2 * iz2, "must be z1 + 2*z2 = "// &
          int_str(iz1 + 2 * iz2)//" (coaxial sun, satellites and ring; got "//int_str(iz3)//")")
        call rules%require_rule("k"//at, is_set(k(i)), "missing (number of satellites)")
        call rules%require_rule("k"//at, .not. k(i) < 1.0_wp, "must be >= 1 (got "//number_str(k(i))//")")
        call rules%require_whole("k"//at, k(i), 1, huge(1), ik)
        call rules%require_rule("k"//at, modulo(iz1 + iz3, ik) == 0, "(z1 + z3)/k must be an integer "// &
          "for equally spaced satellites (z1 + z3 = "//int_str(iz1 + iz3)//", k = "//int_str(ik)//")")
        if (ik >= 2) then
          call rules%require_rule("k"//at, real(iz1 + iz2, wp) * sin(pi / real(ik, wp)) > real(iz2 + 2, wp), &
            "too many satellites: neighbours collide, (z1 + z2)*sin(180/k) must exceed z2 + 2")
        end if
        deck%st(i)%z3 = iz3
        deck%st(i)%k = ik
        call pressure_angle(rules, "alpha_w23"//at, alpha_w23(i), alpha_w(i), deck%st(i)%alpha_w23)
        if (.not. is_set(gamma(i))) deck%st(i)%gamma = 0.5_wp * pi
      else
        call not_used_int(rules, "z3"//at, z3(i), kind)
        call not_used_int(rules, "k"//at, k(i), kind)
        call rules%require_rule("alpha_w23"//at, .not. is_set(alpha_w23(i)) .or. alpha_w23(i) == 0.0_wp, &
          "only for a 'planetary' stage: leave it 0 or unset")
      end if
      if (rules%failed(error)) return
    end do
  end subroutine read_gears_deck

  !> The required values of every stage of a known kind (the input torque m1 unless a later
  !> stage of a series, the teeth z1, z2, the module m unless dw1 is given, and z3, k of a
  !> planetary stage): when two or more are missing, one error naming them all.
  subroutine require_all_stages(rules, series, stage, m1, z1, z2, z3, k, m, dw1)
    type(deck_rules_t), intent(inout) :: rules
    !> Layout 'series': the torque of a later stage comes from the stage before.
    logical, intent(in) :: series
    !> Stage kinds as given, one per stage.
    character(*), intent(in) :: stage(:)
    !> Deck values per stage (unset_real when not given).
    real(wp), intent(in) :: m1(:), z1(:), z2(:), z3(:), k(:), m(:), dw1(:)
    character(len=16), allocatable :: names(:)
    real(wp), allocatable :: values(:)
    character(len=:), allocatable :: at
    integer :: i, kind
    allocate (names(0), values(0))
    do i = 1, size(stage)
      kind = findloc(gear_kind_names, lower(trim(adjustl(stage(i)))), dim=1)
      if (kind == 0) cycle
      at = "("//int_str(i)//")"
      if (.not. (series .and. i > 1)) then
        names = [character(len=16) :: names, "m1"//at]
        values = [values, m1(i)]
      end if
      names = [character(len=16) :: names, "z1"//at, "z2"//at]
      values = [values, z1(i), z2(i)]
      if (.not. is_set(dw1(i))) then
        names = [character(len=16) :: names, "m"//at]
        values = [values, m(i)]
      end if
      if (kind == gear_planetary) then
        names = [character(len=16) :: names, "z3"//at, "k"//at]
        values = [values, z3(i), k(i)]
      end if
    end do
    if (count(.not. is_set(values)) >= 2) call rules%require_all_set(names, values)
  end subroutine require_all_stages

  !> A pressure angle in deg: optional with `default` (itself possibly unset -> 20 deg),
  !> finite and strictly inside (0, 45) deg; returned in rad.
  subroutine pressure_angle(rules, name, value, default, angle)
    type(deck_rules_t), intent(inout) :: rules
    character(*), intent(in) :: name
    real(wp), intent(in) :: value, default
    real(wp), intent(out) :: angle
    real(wp) :: a
    angle = 0.0_wp
    if (is_set(value)) then
      a = value
    else if (is_set(default)) then
      a = default
    else
      a = alpha_default
    end if
    call rules%require_in(name, a, a > 0.0_wp .and. a < 45.0_wp, "(0, 45) deg")
    if (rules%ok()) angle = a * deg_to_rad
  end subroutine pressure_angle

  !> Teeth count: present and a whole number from 1 to max_teeth.
  subroutine require_teeth(rules, name, z, teeth)
    type(deck_rules_t), intent(inout) :: rules
    character(*), intent(in) :: name
    !> Deck value (an integer deck variable, read as a real).
    real(wp), intent(in) :: z
    !> The count.
    integer, intent(out) :: teeth
    teeth = 0
    if (.not. is_set(z)) then
      call rules%require_rule(name, .false., "missing (number of teeth)")
    else if (z < 1.0_wp) then
      call rules%require_rule(name, .false., "must be >= 1 teeth (got "//number_str(z)//")")
    else if (z > real(max_teeth, wp)) then
      call rules%require_rule(name, .false., "must be <= "//int_str(max_teeth)//" teeth (got "//number_str(z)//")")
    else
      call rules%require_whole(name, z, 1, max_teeth, teeth)
    end if
  end subroutine require_teeth

  !> A planetary-only integer on another stage: unset or 0.
  subroutine not_used_int(rules, name, value, kind)
    type(deck_rules_t), intent(inout) :: rules
    character(*), intent(in) :: name
    !> Deck value (an integer deck variable, read as a real).
    real(wp), intent(in) :: value
    integer, intent(in) :: kind
    call rules%require_rule(name, .not. is_set(value) .or. value == 0.0_wp, "only for a 'planetary' stage (this one "// &
      "is '"//trim(gear_kind_names(kind))//"'): leave it 0 or unset")
  end subroutine not_used_int

  !> No real value beyond the last stage.
  subroutine no_extra_real(rules, name, values, n)
    type(deck_rules_t), intent(inout) :: rules
    character(*), intent(in) :: name
    real(wp), intent(in) :: values(:)
    integer, intent(in) :: n
    integer :: i
    do i = n + 1, size(values)
      call rules%require_rule(name//"("//int_str(i)//")", .not. is_set(values(i)), "given for stage "//int_str(i)// &
        " but the deck has "//int_str(n)//" stage(s) (see 'stage')")
    end do
  end subroutine no_extra_real

end module kinetostat_gears_deck
