!> `&planetary_synthesis` decks: reading, validation and the commented template.
module kinetostat_planetary_synthesis_deck
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str, lower
  use kinetostat_deck, only: begin_group, text_bytes, text_chars, deck_context_t, unset_real, deck_source_t, &
    namelist_probe_t, deck_error, is_set, optional_default, deck_rules_t
  use kinetostat_planetary_synthesis, only: planetary_spec_t, max_ring_teeth
  implicit none
  private
  public :: planetary_synthesis_deck_t, read_planetary_synthesis_deck, planetary_synthesis_template

  !> A validated `&planetary_synthesis` deck.
  type :: planetary_synthesis_deck_t
    !> What the train must do.
    type(planetary_spec_t) :: spec
    !> Module, mm, for the analysis deck (--format deck); whether given.
    logical :: has_m = .false.
    real(wp) :: m = 0.0_wp
    !> Torque on the sun for the analysis deck, N*m; whether given.
    logical :: has_m1 = .false.
    real(wp) :: m1 = 0.0_wp
  end type planetary_synthesis_deck_t

  !> Template deck, one line per entry.
  character(*), parameter :: planetary_synthesis_template(*) = [character(len=100) :: &
    "! kinetostat deck: tooth numbers of a single-row planetary train: sun 1 (input), planets 2", &
    "! on the carrier H (output), fixed ring 3 with internal teeth; u = u_1H = 1 + z3/z1.", &
    "&planetary_synthesis", &
    "  scheme      = 'single_row'  ! the train (single_row; default)", &
    "  u           = 5       ! ratio u_1H asked, > 2", &
    "  k           = 3       ! planets, >= 1", &
    "  u_tolerance = 0.04    ! |u_1H - u| <= u_tolerance*u, in [0, 0.5); default 0.04", &
    "  z_min       = 17      ! least teeth of the sun and the planets; default 17", &
    "  z_ring_min  = 85      ! least teeth of the ring; default 85", &
    "  ! m  = 2.5            ! mm, module: only for --format deck (the &gears deck)", &
    "  ! m1 = 100            ! N*m, torque on the sun: only for --format deck", &
    "/"]

contains

  !> Read and validate a `&planetary_synthesis` deck.
  subroutine read_planetary_synthesis_deck(source, deck, error)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> The validated deck.
    type(planetary_synthesis_deck_t), intent(out) :: deck
    !> Input error naming deck, group, variable and reason.
    type(error_t), allocatable, intent(out) :: error
    character(len=text_bytes * text_chars) :: scheme
    real(wp) :: u, k, u_tolerance, z_min, z_ring_min, m, m1
    type(deck_context_t) :: ctx
    type(deck_rules_t) :: rules
    type(namelist_probe_t) :: probe
    namelist /planetary_synthesis/ scheme, u, k, u_tolerance, z_min, z_ring_min, m, m1

    call begin_group(source, "planetary_synthesis", ctx, error, rules)
    if (allocated(error)) return
    scheme = " "
    u = unset_real; k = unset_real; u_tolerance = unset_real; z_min = unset_real; z_ring_min = unset_real
    m = unset_real; m1 = unset_real
    read (source%records, nml=planetary_synthesis, iostat=probe%ios, iomsg=probe%msg)
    do while (probe%retry(source))
      read (probe%records, nml=planetary_synthesis, iostat=probe%ios, iomsg=probe%msg)
    end do
    if (probe%failed(source, ctx, error)) return

    select case (lower(trim(adjustl(scheme))))
    case ("", "single_row")
    case default
      call deck_error(ctx, "scheme", "must be 'single_row' (sun, planets, fixed ring; got '"//trim(scheme)//"')", error)
      return
    end select
    call rules%require_all_set([character(len=1) :: "u", "k"], [u, k])
    call rules%require_set("u", u)
    call rules%require_rule("u", u > 2.0_wp .and. u <= 1000.0_wp, "must be in (2, 1000]: u_1H = 1 + z3/z1 with "// &
      "z3 = z1 + 2 z2 > z1 (got "//real_str(u)//")")
    call rules%require_whole("k", k, 1, 100, deck%spec%k)
    u_tolerance = optional_default(u_tolerance, 0.04_wp)
    call rules%require_in("u_tolerance", u_tolerance, u_tolerance >= 0.0_wp .and. u_tolerance < 0.5_wp, "[0, 0.5)")
    z_min = optional_default(z_min, 17.0_wp)
    call rules%require_whole("z_min", z_min, 1, 1000, deck%spec%z_min)
    z_ring_min = optional_default(z_ring_min, 85.0_wp)
    call rules%require_whole("z_ring_min", z_ring_min, 1, max_ring_teeth, deck%spec%z_ring_min)
    if (is_set(m)) call rules%require_positive("m", m)
    if (is_set(m1)) call rules%require_set("m1", m1)
    if (rules%failed(error)) return
    deck%spec%u = u
    deck%spec%u_tolerance = u_tolerance
    deck%has_m = is_set(m)
    if (deck%has_m) deck%m = m
    deck%has_m1 = is_set(m1)
    if (deck%has_m1) deck%m1 = m1
  end subroutine read_planetary_synthesis_deck

end module kinetostat_planetary_synthesis_deck
