!> T.FTN run: deck -> all steps -> legacy table (appendix 2's two lines per step) or CSV.
module kinetostat_sixbar_report
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t, fatal_error, exit_geometry, exit_input
  use kinetostat_text, only: real_str, int_str
  use kinetostat_output, only: format_csv, run_summary_t, noise_floor, force_columns, angles_pm180, &
    echo_heading, echo_real, echo_int, echo_logical, echo_array, &
    write_csv_header, write_csv_row, write_selfcheck_footer
  use kinetostat_sixbar, only: sixbar_step_t, sixbar_step, sixbar_ok, sixbar_open1, sixbar_dead1, &
    sixbar_open2, sixbar_dead2
  use kinetostat_deck, only: deck_source_t
  use kinetostat_sixbar_deck, only: sixbar_deck_t, read_sixbar_deck
  implicit none
  private
  public :: run_sixbar, sixbar_solve, sixbar_csv_columns, sixbar_csv_values

  !> CSV columns, in the spec's order.
  character(*), parameter :: sixbar_csv_columns(*) = [character(len=4) :: &
    "phi1", "F21", "F21G", "F32", "F32G", "F43", "F43G", "F45", "F45G", "F36", "F36G", &
    "F16", "F16G", "F56", "M1"]
  !> Title line of the table.
  character(*), parameter :: title_fmt = '(1x,a)'
  !> Results header: appendix 2's two lines (F0 = crank angle), then units and frames.
  character(*), parameter :: header_lines(*) = [character(len=108) :: &
    "       F0         F21         F32         F43         F45         F36         F16         F56          M1", &
    "                 F21G        F32G        F43G        F45G        F36G        F16G", &
    "      deg           N           N           N           N           N           N           N         N*m", &
    "                deg/x1      deg/x1      deg/x2      deg/x2      deg/x1      deg/x1"]
  !> Step line 1: crank angle, six force magnitudes, signed F56, driving moment (fields below).
  character(*), parameter :: step_line1_fmt = '(a9,8a12)'
  !> Step line 2: the six force angles under their magnitudes.
  character(*), parameter :: step_line2_fmt = '(9x,6a12)'
  !> A table field that fits: fixed point with 2 (M1: 3) decimals.
  character(*), parameter :: field_f2_fmt = '(f40.2)', field_f3_fmt = '(f40.3)'
  !> A table field too wide for fixed point (from 1e7 or 1e8, N or N*m): exponent form.
  character(*), parameter :: field_es_fmt = '(es11.4)'

contains

  !> All steps of a validated deck; a step that cannot be assembled (or is a dead position)
  !> is a geometry error naming the step number and the crank angle.
  subroutine sixbar_solve(path, deck, steps, error)
    !> Deck file, for the message.
    character(*), intent(in) :: path
    !> Validated deck.
    type(sixbar_deck_t), intent(in) :: deck
    !> One result per crank step.
    type(sixbar_step_t), allocatable, intent(out) :: steps(:)
    !> Geometry error (exit 3), or overflow (exit 2).
    type(error_t), allocatable, intent(out) :: error
    integer :: k
    allocate (steps(deck%n))
    do k = 1, deck%n
      steps(k) = sixbar_step(deck%p, deck%phi1_deg(k) * deg_to_rad, deck%f5(k))
      if (steps(k)%status /= sixbar_ok) then
        call fatal_error(error, exit_geometry, path//": &sixbar: step "//int_str(k)//" (phi1 = "// &
          real_str(deck%phi1_deg(k))//" deg): "//failure_text(deck, steps(k)))
        return
      end if
      if (.not. all(ieee_is_finite(sixbar_csv_values(steps(k), deck%p%l1)))) then
        call fatal_error(error, exit_input, path//": &sixbar: step "//int_str(k)//" (phi1 = "// &
          real_str(deck%phi1_deg(k))//" deg): results overflow (not finite): the deck's magnitudes are out of range")
        return
      end if
    end do
  end subroutine sixbar_solve

  !> Why a position failed, with the numbers.
  function failure_text(deck, s) result(text)
    type(sixbar_deck_t), intent(in) :: deck
    type(sixbar_step_t), intent(in) :: s
    character(len=:), allocatable :: text
    real(wp) :: l2, l3
    l2 = deck%p%lam2 * deck%p%l1
    l3 = deck%p%lam3 * deck%p%l1
    select case (s%status)
    case (sixbar_open1)
      text = "contour A-B-C-D cannot be assembled: |BD| = "//real_str(s%pos%detail)// &
        " m is outside [|l2 - l3|, l2 + l3] = ["//real_str(abs(l2 - l3))//", "//real_str(l2 + l3)//"] m"
    case (sixbar_dead1)
      text = "dead position of contour A-B-C-D: B, C, D in line (sin(phi3 - phi2) = "// &
        real_str(s%pos%detail)//"), reactions undetermined"
    case (sixbar_open2)
      text = "contour D-E-H cannot be assembled: |e - y_E| = "//real_str(s%pos%detail)// &
        " m exceeds l4 = "//real_str(deck%p%lam4 * deck%p%l1)//" m"
    case (sixbar_dead2)
      text = "dead position of contour D-E-H: link 4 perpendicular to the guide (cos(phi4) = "// &
        real_str(s%pos%detail)//"), reactions undetermined"
    case default
      text = "position failure "//int_str(s%status)
    end select
  end function failure_text

  !> Read the deck, compute every step, then write the table or CSV to `unit`.
  !> Nothing is written unless the whole run succeeded.
  subroutine run_sixbar(source, output_format, unit, error, summary)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> `format_table` or `format_csv`.
    integer, intent(in) :: output_format
    !> Output unit.
    integer, intent(in) :: unit
    !> Input or geometry error.
    type(error_t), allocatable, intent(out) :: error
    !> Self-check figures of the run.
    type(run_summary_t), intent(out), optional :: summary
    type(sixbar_deck_t) :: deck
    type(sixbar_step_t), allocatable :: steps(:)

    call read_sixbar_deck(source, deck, error)
    if (allocated(error)) return
    call sixbar_solve(source%path, deck, steps, error)
    if (allocated(error)) return
    if (present(summary)) summary = run_summary_t(size(steps), maxval(steps%residual), &
                                                  maxval(steps%mismatch), "M1")
    if (output_format == format_csv) then
      call write_sixbar_csv(unit, deck, steps)
    else
      call write_sixbar_table(unit, source%path, deck, steps)
    end if
  end subroutine run_sixbar

  !> The row of CSV values of one step. Forces below `noise_rel` times the step's largest
  !> force (and M1 below that force times l1) are roundoff: printed as 0 with angle 0.
  pure function sixbar_csv_values(s, l1) result(v)
    !> One computed step.
    type(sixbar_step_t), intent(in) :: s
    !> Crank length, m (moment scale).
    real(wp), intent(in) :: l1
    real(wp) :: v(size(sixbar_csv_columns))
    real(wp) :: floor, f(2, 6)
    f = reshape([s%f21, s%f32, s%f43, s%f45, s%f36, s%f16], [2, 6])
    floor = noise_floor(f, [s%f56])
    v(1) = s%pos%phi1 * rad_to_deg
    v(2:13) = force_columns(f, floor, angles_pm180)
    v(14) = s%f56
    if (abs(v(14)) <= floor) v(14) = 0.0_wp
    v(15) = s%m1
    if (abs(v(15)) <= floor * l1) v(15) = 0.0_wp
  end function sixbar_csv_values

  subroutine write_sixbar_csv(unit, deck, steps)
    integer, intent(in) :: unit
    type(sixbar_deck_t), intent(in) :: deck
    type(sixbar_step_t), intent(in) :: steps(:)
    integer :: k
    call write_csv_header(unit, sixbar_csv_columns)
    do k = 1, size(steps)
      call write_csv_row(unit, sixbar_csv_values(steps(k), deck%p%l1))
    end do
  end subroutine write_sixbar_csv

  subroutine write_sixbar_table(unit, path, deck, steps)
    integer, intent(in) :: unit
    character(*), intent(in) :: path
    type(sixbar_deck_t), intent(in) :: deck
    type(sixbar_step_t), intent(in) :: steps(:)
    real(wp) :: v(size(sixbar_csv_columns))
    integer :: k, i

    write (unit, title_fmt) "KINETOSTAT  T.FTN  FORCE ANALYSIS OF THE SIX-BAR CRANK-ROCKER-SLIDER MECHANISM"
    write (unit, title_fmt) "DECK: "//path
    call echo_heading(unit, "INPUT DATA")
    call echo_real(unit, "A", deck%p%a, "m")
    call echo_real(unit, "B", deck%p%b, "m")
    call echo_real(unit, "L1", deck%p%l1, "m")
    call echo_real(unit, "LAM2", deck%p%lam2, "l_BC/l1")
    call echo_real(unit, "LAM_S2", deck%p%lam_s2, "l_BS2/l_BC")
    call echo_real(unit, "LAM3", deck%p%lam3, "l_DC/l1")
    call echo_real(unit, "LAM_DE", deck%p%lam_de, "l_DE/l1")
    call echo_real(unit, "LAM4", deck%p%lam4, "l_EH/l1")
    call echo_real(unit, "LAM_S4", deck%p%lam_s4, "l_ES4/l_EH")
    call echo_real(unit, "LAM_E", deck%p%lam_e, "e/l1")
    call echo_real(unit, "M1", deck%p%m1, "kg")
    call echo_real(unit, "M2", deck%p%m2, "kg")
    call echo_real(unit, "M3", deck%p%m3, "kg")
    call echo_real(unit, "M4", deck%p%m4, "kg")
    call echo_real(unit, "M5", deck%p%m5, "kg")
    call echo_real(unit, "J1", deck%p%j1, "kg*m^2")
    call echo_real(unit, "J2", deck%p%j2, "kg*m^2")
    call echo_real(unit, "J3", deck%p%j3, "kg*m^2")
    call echo_real(unit, "J4", deck%p%j4, "kg*m^2")
    call echo_real(unit, "OMEGA1", deck%p%omega1, "rad/s")
    call echo_real(unit, "G", deck%p%g, "m/s^2")
    call echo_logical(unit, "START_AT_EXTREME", deck%start_at_extreme, "")
    call echo_real(unit, "PHI_START", deck%phi_start, "deg (frame 1)")
    call echo_real(unit, "DPHI", deck%dphi, "deg")
    call echo_int(unit, "N", deck%n, "steps")
    call echo_array(unit, "F5", deck%f5, "N (along +x2)")
    call echo_logical(unit, "LEGACY_EQ2", deck%p%legacy_eq2, "(1991 erratum in eps_q2)")

    call echo_heading(unit, "RESULTS")
    do k = 1, size(header_lines)
      write (unit, '(a)') trim(header_lines(k))
    end do
    do k = 1, size(steps)
      v = sixbar_csv_values(steps(k), deck%p%l1)
      write (unit, step_line1_fmt) field(v(1), 9, field_f2_fmt), &
        (field(v(i), 12, field_f2_fmt), i=2, 14, 2), field(v(15), 12, field_f3_fmt)
      write (unit, step_line2_fmt) (field(v(i), 12, field_f2_fmt), i=3, 13, 2)
    end do
    call write_selfcheck_footer(unit, maxval(steps%residual), maxval(steps%mismatch), "M1")
  end subroutine write_sixbar_table

  !> One right-justified table field of `width` characters: `fixed_fmt` when it fits
  !> (leaving one blank), otherwise the exponent form, so a table never shows '*'.
  pure function field(x, width, fixed_fmt) result(text)
    !> Value.
    real(wp), intent(in) :: x
    !> Field width, characters (9 or 12).
    integer, intent(in) :: width
    !> Fixed-point format, wide enough for any value, e.g. '(f40.2)'.
    character(*), intent(in) :: fixed_fmt
    character(len=width) :: text
    character(len=40) :: buf
    write (buf, fixed_fmt) x + 0.0_wp
    buf = adjustl(buf)
    if (len_trim(buf) >= width) then
      write (buf, field_es_fmt) x + 0.0_wp
      buf = adjustl(buf)
    end if
    text = adjustr(buf(1:width))
  end function field

end module kinetostat_sixbar_report
