!> The registry of mechanisms: the one place that maps a deck's first namelist group
!> (or a `template KIND`) to the mechanism's run and template routines.
!> Adding a mechanism = its own modules + one `case` in each routine here.
module kinetostat_mechanisms
  use kinetostat_error, only: error_t, fatal_error, exit_input, exit_usage
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name
  use kinetostat_output, only: run_summary_t
  use kinetostat_pr3207_report, only: run_pr3207
  use kinetostat_pr3207_deck, only: write_pr3207_template
  use kinetostat_pr3050_report, only: run_pr3050
  use kinetostat_pr3050_deck, only: write_pr3050_template
  use kinetostat_sixbar_report, only: run_sixbar
  use kinetostat_sixbar_deck, only: write_sixbar_template
  use kinetostat_gears_report, only: run_gears
  use kinetostat_gears_deck, only: write_gears_template
  use kinetostat_cam_report, only: run_cam
  use kinetostat_cam_deck, only: write_cam_template
  use kinetostat_assur_report, only: run_assur
  use kinetostat_assur_deck, only: write_assur_template
  implicit none
  private
  public :: run_deck, write_template, known_kinds

  !> Mechanism kinds (namelist group names) the program knows, for messages and --help.
  character(*), parameter :: known_kinds = "pr3207, pr3050, sixbar, assur, gears, cam"

contains

  !> Run the mechanism named by the deck's first namelist group; write to `unit`.
  subroutine run_deck(path, output_format, unit, error, summary)
    !> Deck file.
    character(*), intent(in) :: path
    !> `format_table` or `format_csv`.
    integer, intent(in) :: output_format
    !> Output unit.
    integer, intent(in) :: unit
    !> Input or geometry error.
    type(error_t), allocatable, intent(out) :: error
    !> Self-check figures (steps = 0 when the mechanism has none).
    type(run_summary_t), intent(out) :: summary
    character(len=:), allocatable :: group
    type(deck_source_t) :: source
    call load_deck(path, source, error)
    if (allocated(error)) return
    call read_group_name(source, group, error)
    if (allocated(error)) return
    select case (group)
    case ("pr3207")
      call run_pr3207(source, output_format, unit, error, summary)
    case ("pr3050")
      call run_pr3050(source, output_format, unit, error, summary)
    case ("sixbar")
      call run_sixbar(source, output_format, unit, error, summary)
    case ("gears")
      call run_gears(source, output_format, unit, error, summary)
    case ("cam")
      call run_cam(source, output_format, unit, error, summary)
    case ("assur")
      call run_assur(source, output_format, unit, error, summary)
    case default
      call fatal_error(error, exit_input, path//": &"//group// &
        ": unknown mechanism (known: "//known_kinds//")")
    end select
  end subroutine run_deck

  !> Print the commented template deck of a mechanism kind.
  subroutine write_template(kind, unit, error)
    !> Namelist group name of the mechanism.
    character(*), intent(in) :: kind
    !> Output unit.
    integer, intent(in) :: unit
    !> Usage error for an unknown kind.
    type(error_t), allocatable, intent(out) :: error
    select case (kind)
    case ("pr3207")
      call write_pr3207_template(unit)
    case ("pr3050")
      call write_pr3050_template(unit)
    case ("sixbar")
      call write_sixbar_template(unit)
    case ("gears")
      call write_gears_template(unit)
    case ("cam")
      call write_cam_template(unit)
    case ("assur")
      call write_assur_template(unit)
    case default
      call fatal_error(error, exit_usage, "template: unknown kind '"//kind//"' (known: "//known_kinds//")")
    end select
  end subroutine write_template

end module kinetostat_mechanisms
