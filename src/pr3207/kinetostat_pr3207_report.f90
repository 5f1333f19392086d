!> PR 3207 run: deck -> all steps -> legacy table (two lines per step) or CSV.
module kinetostat_pr3207_report
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t
    use kinetostat_output, only: format_csv, run_summary_t, noise_floor, force_columns, angles_0_360, &
    echo_heading, echo_real, echo_int, echo_array, &
    write_csv_header, write_csv_row, write_selfcheck_footer
  use kinetostat_pr3207, only: pr3207_step_t, pr3207_step
  use kinetostat_deck, only: deck_source_t
  use kinetostat_pr3207_deck, only: pr3207_deck_t, read_pr3207_deck
  implicit none
  private
  public :: run_pr3207, pr3207_solve, pr3207_csv_columns, pr3207_csv_values

  !> CSV columns, in the spec's order.
  character(*), parameter :: pr3207_csv_columns(*) = [character(len=4) :: &
    "phi1", "F16", "F16G", "F21", "F21G", "F36", "F36G", "F34", "F34G", "F56", "F56G", "M1"]
  !> Title line of the table.
  character(*), parameter :: title_fmt = '(1x,a)'
  !> Results header, line 1 (magnitudes) and 2 (angles), with units.
  character(*), parameter :: header_lines(*) = [character(len=88) :: &
    "     PHI1         F16         F21         F36         F34         F56          M1", &
    "                 F16G        F21G        F36G        F34G        F56G", &
    "      deg           N           N           N           N           N         N*m", &
    "                  deg         deg         deg         deg         deg"]
  !> Step line 1: crank angle, five force magnitudes, driving moment.
  character(*), parameter :: step_line1_fmt = '(f9.2,5f12.2,f12.3)'
  !> Step line 2: the five force angles under their magnitudes.
  character(*), parameter :: step_line2_fmt = '(9x,5f12.2)'

contains

  !> All steps of a validated deck.
  pure subroutine pr3207_solve(deck, steps)
    !> Validated deck.
    type(pr3207_deck_t), intent(in) :: deck
    !> One result per crank step.
    type(pr3207_step_t), allocatable, intent(out) :: steps(:)
    integer :: k
    allocate (steps(deck%n))
    do k = 1, deck%n
      steps(k) = pr3207_step(deck%p, deck%phi1_deg(k) * deg_to_rad, deck%f5c(k))
    end do
  end subroutine pr3207_solve

  !> Read the deck, compute every step, then write the table or CSV to `unit`.
  !> Nothing is written unless the whole run succeeded.
  subroutine run_pr3207(source, output_format, unit, error, summary)
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> `format_table` or `format_csv`.
    integer, intent(in) :: output_format
    !> Output unit.
    integer, intent(in) :: unit
    !> Input error from the deck.
    type(error_t), allocatable, intent(out) :: error
    !> Self-check figures of the run.
    type(run_summary_t), intent(out), optional :: summary
    type(pr3207_deck_t) :: deck
    type(pr3207_step_t), allocatable :: steps(:)

    call read_pr3207_deck(source, deck, error)
    if (allocated(error)) return
    call pr3207_solve(deck, steps)
    if (present(summary)) summary = run_summary_t(size(steps), maxval(steps%residual), &
                                                  maxval(steps%mismatch), "M1")
    if (output_format == format_csv) then
      call write_pr3207_csv(unit, deck, steps)
    else
      call write_pr3207_table(unit, source%path, deck, steps)
    end if
  end subroutine run_pr3207

  !> The row of CSV values of one step. Forces below `noise_rel` times the step's largest
  !> force (and M1 below that force times l_AB) are roundoff: printed as 0 with angle 0.
  pure function pr3207_csv_values(s, l_ab) result(v)
    type(pr3207_step_t), intent(in) :: s
    !> Crank length, m (moment scale).
    real(wp), intent(in) :: l_ab
    real(wp) :: v(size(pr3207_csv_columns))
    real(wp) :: floor, f(2, 5)
    f = reshape([s%f16, s%f21, s%f36, s%f34, s%f56], [2, 5])
    floor = noise_floor(f, [real(wp) ::])
    v(1) = s%phi1 * rad_to_deg
    v(2:11) = force_columns(f, floor, angles_0_360)
    v(12) = s%m1
    if (abs(v(12)) <= floor * l_ab) v(12) = 0.0_wp
  end function pr3207_csv_values

  subroutine write_pr3207_csv(unit, deck, steps)
    integer, intent(in) :: unit
    type(pr3207_deck_t), intent(in) :: deck
    type(pr3207_step_t), intent(in) :: steps(:)
    integer :: k
    call write_csv_header(unit, pr3207_csv_columns)
    do k = 1, size(steps)
      call write_csv_row(unit, pr3207_csv_values(steps(k), deck%p%l_ab))
    end do
  end subroutine write_pr3207_csv

  subroutine write_pr3207_table(unit, path, deck, steps)
    integer, intent(in) :: unit
    character(*), intent(in) :: path
    type(pr3207_deck_t), intent(in) :: deck
    type(pr3207_step_t), intent(in) :: steps(:)
    real(wp) :: v(size(pr3207_csv_columns))
    integer :: k

    write (unit, title_fmt) "KINETOSTAT  PR 3207  FORCE ANALYSIS OF THE SIX-BAR SLOTTED-LINK (SHAPER) MECHANISM"
    write (unit, title_fmt) "DECK: "//path
    call echo_heading(unit, "INPUT DATA")
    call echo_real(unit, "L_AB", deck%p%l_ab, "m")
    call echo_real(unit, "L_AC", deck%p%l_ac, "m")
    call echo_real(unit, "L_CD", deck%p%l_cd, "m")
    call echo_real(unit, "L_CS3", deck%p%l_cs3, "m")
    call echo_real(unit, "M1", deck%p%m1, "kg")
    call echo_real(unit, "M3", deck%p%m3, "kg")
    call echo_real(unit, "M5", deck%p%m5, "kg")
    call echo_real(unit, "J3", deck%p%j3, "kg*m^2")
    call echo_real(unit, "OMEGA1", deck%p%omega1, "rad/s")
    call echo_real(unit, "G", deck%p%g, "m/s^2")
    call echo_real(unit, "PHI_START", deck%phi_start, "deg")
    call echo_real(unit, "DPHI", deck%dphi, "deg")
    call echo_int(unit, "N", deck%n, "steps")
    if (deck%two_value) then
      call echo_real(unit, "F5C_WORK", deck%f5c_work, "N")
      call echo_real(unit, "F5C_IDLE", deck%f5c_idle, "N")
      call echo_real(unit, "PHI_CUT_START", deck%phi_cut_start, "deg")
      call echo_real(unit, "PHI_CUT_END", deck%phi_cut_end, "deg")
    else
      call echo_array(unit, "F5C", deck%f5c, "N")
    end if

    call echo_heading(unit, "RESULTS")
    do k = 1, size(header_lines)
      write (unit, '(a)') trim(header_lines(k))
    end do
    do k = 1, size(steps)
      v = pr3207_csv_values(steps(k), deck%p%l_ab)
      write (unit, step_line1_fmt) v(1), v(2), v(4), v(6), v(8), v(10), v(12)
      write (unit, step_line2_fmt) v(3), v(5), v(7), v(9), v(11)
    end do
    call write_selfcheck_footer(unit, maxval(steps%residual), maxval(steps%mismatch), "M1")
  end subroutine write_pr3207_table

end module kinetostat_pr3207_report
