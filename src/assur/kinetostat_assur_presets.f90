!> Presets of the generic engine (&assur decks) that `kinetostat template NAME` prints: a
!> crank-rocker four-bar and an engine slider-crank with a gas force on the piston. They are
!> the tutorial's decks (docs/examples/, compared byte for byte by test/cli/test_templates.sh).
module kinetostat_assur_presets
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: assur_preset, preset_names

  !> Names of the presets, for messages and --help.
  character(*), parameter :: preset_names = "fourbar, engine"

  !> `kinetostat template fourbar`: a crank-rocker four-bar (docs/examples/fourbar.nml).
  character(*), parameter :: fourbar_lines(*) = [character(len=80) :: &
    "! A crank-rocker four-bar: frame 0, crank 1 (AB), coupler 2 (BC), rocker 3 (DC).", &
    "&assur", &
    "  title = 'crank-rocker four-bar'", &
    "  frame_id = 0, crank_id = 1", &
    "  crank_at = 0, 0                ! m, crank pivot A", &
    "  omega1 = 20                    ! rad/s, counter-clockwise", &
    "  phi_start = 0, dphi = 15       ! deg", &
    "  ! dyad 1: RRR. Coupler 2 pinned to the crank pin B = (0.1, 0) of link 1,", &
    "  ! rocker 3 pivoted on the frame at D = (0.3, 0); BC = 0.35 m, DC = 0.25 m.", &
    "  dyad(1)%kind = 1, dyad(1)%link2 = 2, dyad(1)%link3 = 3", &
    "  dyad(1)%on2 = 1, dyad(1)%at2 = 0.1, 0", &
    "  dyad(1)%on3 = 0, dyad(1)%at3 = 0.3, 0", &
    "  dyad(1)%l2 = 0.35, dyad(1)%l3 = 0.25, dyad(1)%mode = 1", &
    "  dyad(1)%m2 = 1.0, dyad(1)%j2 = 0.0102, dyad(1)%s2 = 0.175, 0", &
    "  dyad(1)%m3 = 0.8, dyad(1)%j3 = 0.0042, dyad(1)%s3 = 0.125, 0", &
    "  ! a resisting moment of 20 N*m on the rocker (clockwise)", &
    "  moment(1)%link = 3, moment(1)%value = -20", &
    "/"]

  !> `kinetostat template engine`: a four-stroke engine slider-crank with the gas force of
  !> its working cycle over the crank angle 0..720 deg (docs/examples/engine.nml).
  character(*), parameter :: engine_lines(*) = [character(len=96) :: &
    "! A four-stroke engine slider-crank: frame 0, crank 1 (AB), connecting rod 2 (BC), piston 3 (C).", &
    "! The gas force on the piston over the crank angle 0..720 deg (one working cycle), from", &
    "! the indicator diagram of a bore of 80 mm, compression ratio 9, peak 55 bar at 375 deg.", &
    "&assur", &
    "  title = 'four-stroke engine slider-crank with its gas force'", &
    "  frame_id = 0, crank_id = 1", &
    "  crank_at = 0, 0", &
    "  crank_m = 3.0, crank_j = 0.004, crank_s = 0, 0   ! counterweighted: centre on the pivot", &
    "  omega1 = 300                   ! rad/s (2865 rpm), counter-clockwise", &
    "  phi_start = 0, dphi = 15, n = 49   ! deg, two turns; 0 = top dead centre, start of intake", &
    "  dyad(1)%kind = 2, dyad(1)%link2 = 2, dyad(1)%link3 = 3", &
    "  dyad(1)%on2 = 1, dyad(1)%at2 = 0.05, 0     ! m, crank pin B (crank radius 50 mm)", &
    "  dyad(1)%on3 = 0, dyad(1)%at3 = 0, 0        ! the cylinder axis: the x-axis through A", &
    "  dyad(1)%angle3 = 0", &
    "  dyad(1)%l2 = 0.2, dyad(1)%mode = 1         ! rod 200 mm; piston at x > 0", &
    "  dyad(1)%m2 = 1.2, dyad(1)%j2 = 0.005, dyad(1)%s2 = 0.06, 0", &
    "  dyad(1)%m3 = 0.8", &
    "  ! gas force on the piston, towards the crank (-x), N, over the crank angle (deg):", &
    "  ! intake 0..180, compression 180..360, combustion and expansion 360..540, exhaust 540..720", &
    "  force(1)%link = 3, force(1)%at = 0, 0, force(1)%angle = 180, force(1)%over = 1", &
    "  force(1)%table = 0, -50, 30, -50, 60, -50, 90, -50, 120, -50, 150, -50, 180, -50,", &
    "    210, -21, 240, 89, 270, 375, 300, 1195, 330, 3924, 345, 6606, 360, 8282,", &
    "    365, 14569, 370, 20856, 375, 27143, 380, 23604, 390, 17019, 405, 10222, 420, 6459,", &
    "    450, 3186, 480, 2019, 510, 1568, 540, 1446, 560, 75, 600, 75, 660, 75, 720, -50", &
    "/"]

contains

  !> The preset deck called `name` into `out`; `found` is false for an unknown name.
  pure subroutine assur_preset(name, out, found)
    !> Preset name ("fourbar", "engine").
    character(*), intent(in) :: name
    !> Where the deck's lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Whether `name` is a preset.
    logical, intent(out) :: found
    found = .true.
    select case (name)
    case ("fourbar")
      call out%put_lines(fourbar_lines)
    case ("engine")
      call out%put_lines(engine_lines)
    case default
      found = .false.
    end select
  end subroutine assur_preset

end module kinetostat_assur_presets
