!> PR 3207 as a mechanism of the run pipeline: deck -> every crank step -> step table, and
!> the legacy table layout of the 1991 printout (two lines per step).
module kinetostat_pr3207_layout
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t
  use kinetostat_noise, only: noise_floor, force_columns, angles_0_360
  use kinetostat_step_table, only: step_table_t, col_input_angle, col_force, col_force_angle, col_moment
  use kinetostat_format, only: fixed_field
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_table_writer, only: put_two_line_step
  use kinetostat_pr3207, only: pr3207_step_t, pr3207_step
  use kinetostat_pr3207_deck, only: pr3207_deck_t, read_pr3207_deck, write_pr3207_template
  implicit none
  private
  public :: pr3207_mechanism_t, new_pr3207, pr3207_solve, pr3207_csv_columns, pr3207_csv_values

  !> CSV columns, in the spec's order.
  character(*), parameter :: pr3207_csv_columns(*) = [character(len=4) :: &
    "phi1", "F16", "F16G", "F21", "F21G", "F36", "F36G", "F34", "F34G", "F56", "F56G", "M1"]
  !> Units of the columns.
  character(*), parameter :: column_units(*) = [character(len=3) :: &
    "deg", "N", "deg", "N", "deg", "N", "deg", "N", "deg", "N", "deg", "N*m"]
  !> Kinds of the columns.
  integer, parameter :: column_kinds(*) = [col_input_angle, col_force, col_force_angle, col_force, col_force_angle, &
    col_force, col_force_angle, col_force, col_force_angle, col_force, col_force_angle, col_moment]
  !> Results header, line 1 (magnitudes) and 2 (angles), with units.
  character(*), parameter :: header_lines(*) = [character(len=88) :: &
    "     PHI1         F16         F21         F36         F34         F56          M1", &
    "                 F16G        F21G        F36G        F34G        F56G", &
    "      deg           N           N           N           N           N         N*m", &
    "                  deg         deg         deg         deg         deg"]
  !> The same in Russian (units as the 1991 printouts: Н, Н*м, град).
  character(*), parameter :: header_lines_ru(*) = [character(len=100) :: &
    "     PHI1         F16         F21         F36         F34         F56          M1", &
    "                 F16G        F21G        F36G        F34G        F56G", &
    "     град           Н           Н           Н           Н           Н         Н*м", &
    "                  град        град        град        град        град"]

  !> PR 3207: six-bar slotted-link (shaper) mechanism, manual section 3.
  type, extends(mechanism_t) :: pr3207_mechanism_t
    !> The validated deck.
    type(pr3207_deck_t) :: deck
  contains
    procedure :: read_deck
    procedure :: solve
    procedure :: write_results
    procedure :: write_template
  end type pr3207_mechanism_t

contains

  !> A new PR 3207 mechanism (the registry's constructor).
  subroutine new_pr3207(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (pr3207_mechanism_t :: mech)
    mech%title_en = "KINETOSTAT  PR 3207  FORCE ANALYSIS OF THE SIX-BAR SLOTTED-LINK (SHAPER) MECHANISM"
    mech%title_ru = "KINETOSTAT  PR 3207  СИЛОВОЙ РАСЧЕТ ШЕСТИЗВЕННОГО" // &
      " КУЛИСНОГО МЕХАНИЗМА (ПОПЕРЕЧНО-СТРОГАЛЬНОГО)"
  end subroutine new_pr3207

  subroutine read_deck(self, source, error)
    class(pr3207_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_pr3207_deck(source, self%deck, error)
  end subroutine read_deck

  pure subroutine write_template(self, out)
    class(pr3207_mechanism_t), intent(in) :: self
    type(text_buffer_t), intent(inout) :: out
    call write_pr3207_template(out)
  end subroutine write_template

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

  !> Every step into the step table, with the INPUT DATA echo and the self-check.
  subroutine solve(self, table, error)
    class(pr3207_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(pr3207_step_t), allocatable :: steps(:)
    integer :: k
    call pr3207_solve(self%deck, steps)
    call table%set_columns(pr3207_csv_columns, column_units, column_kinds)
    table%input_column = 1
    call table%allocate_rows(size(steps))
    do k = 1, size(steps)
      table%rows(:, k) = pr3207_csv_values(steps(k), self%deck%p%l_ab)
    end do
    call table%set_selfcheck(maxval(steps%residual), maxval(steps%mismatch), "M1")
    call table%note_load(self%deck%f5c)
    call echo_deck(self%deck, table)
  end subroutine solve

  !> The row of values of one step. Forces below `noise_rel` times the step's largest
  !> force (and M1 below that force times l_AB) are roundoff: printed as 0 with angle 0.
  pure function pr3207_csv_values(s, l_ab) result(v)
    !> One computed step.
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

  !> The INPUT DATA echo of the deck.
  pure subroutine echo_deck(deck, table)
    type(pr3207_deck_t), intent(in) :: deck
    type(step_table_t), intent(inout) :: table
    call table%echo_real("L_AB", deck%p%l_ab, "m")
    call table%echo_real("L_AC", deck%p%l_ac, "m")
    call table%echo_real("L_CD", deck%p%l_cd, "m")
    call table%echo_real("L_CS3", deck%p%l_cs3, "m")
    call table%echo_real("M1", deck%p%m1, "kg")
    call table%echo_real("M3", deck%p%m3, "kg")
    call table%echo_real("M5", deck%p%m5, "kg")
    call table%echo_real("J3", deck%p%j3, "kg*m^2")
    call table%echo_real("OMEGA1", deck%p%omega1, "rad/s")
    call table%echo_real("G", deck%p%g, "m/s^2")
    call table%echo_real("PHI_START", deck%phi_start, "deg")
    call table%echo_real("DPHI", deck%dphi, "deg")
    call table%echo_int("N", deck%n, "steps")
    if (deck%two_value) then
      call table%echo_real("F5C_WORK", deck%f5c_work, "N")
      call table%echo_real("F5C_IDLE", deck%f5c_idle, "N")
      call table%echo_real("PHI_CUT_START", deck%phi_cut_start, "deg")
      call table%echo_real("PHI_CUT_END", deck%phi_cut_end, "deg")
    else
      call table%echo_array("F5C", deck%f5c, "N")
    end if
  end subroutine echo_deck

  !> RESULTS: header, then per step the magnitudes (with the crank angle and M1) and under
  !> them the angles, fields 9 and 12 wide as in the original printout.
  pure subroutine write_results(self, table, lang, out)
    class(pr3207_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    type(text_buffer_t), intent(inout) :: out
    integer :: k
    do k = 1, size(header_lines)
      if (lang == lang_ru) then
        call out%put(trim(header_lines_ru(k)))
      else
        call out%put(trim(header_lines(k)))
      end if
    end do
    do k = 1, table%row_count()
      call put_two_line_step(out, table%rows(:, k), [2, 4, 6, 8, 10], [3, 5, 7, 9, 11], &
                             fixed_field(table%rows(12, k), 12, 3))
    end do
  end subroutine write_results

end module kinetostat_pr3207_layout
