!> The registry of mechanisms: one line per kind, (namelist group name, constructor).
!> The list of known kinds, `--help` and `template` come from it. Adding a mechanism = its
!> folder under src/ + one line in `registry_entries`.
module kinetostat_registry
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_deck, only: deck_source_t, deck_source_from_text, read_group_name
  use kinetostat_step_table, only: step_table_t, column_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_pr3207_layout, only: new_pr3207
  use kinetostat_pr3050_layout, only: new_pr3050
  use kinetostat_sixbar_layout, only: new_sixbar
  use kinetostat_assur_layout, only: new_assur
  use kinetostat_gears_layout, only: new_gears
  use kinetostat_cam_layout, only: new_cam
  use kinetostat_linkage_layout, only: new_linkage
  use kinetostat_gear_geometry_layout, only: new_gear_geometry
  use kinetostat_planetary_synthesis_layout, only: new_planetary_synthesis
  use kinetostat_cam_profile_layout, only: new_cam_profile
  implicit none
  private
  public :: create_mechanism, deck_mechanism, known_kinds, known_columns

  abstract interface
    !> Allocate a new mechanism of one kind.
    subroutine constructor_i(mech)
      import :: mechanism_t
      implicit none
      !> The mechanism.
      class(mechanism_t), allocatable, intent(out) :: mech
    end subroutine constructor_i
  end interface

  !> One registered kind.
  type :: registry_entry_t
    !> Namelist group name of the kind's decks.
    character(len=24) :: name = ""
    !> Its constructor.
    procedure(constructor_i), pointer, nopass :: create => null()
  end type registry_entry_t

contains

  !> Every kind the program knows, in the order --help lists them.
  function registry_entries() result(entries)
    type(registry_entry_t), allocatable :: entries(:)
    entries = [ &
      registry_entry_t("pr3207", new_pr3207), &
      registry_entry_t("pr3050", new_pr3050), &
      registry_entry_t("sixbar", new_sixbar), &
      registry_entry_t("assur", new_assur), &
      registry_entry_t("gears", new_gears), &
      registry_entry_t("cam", new_cam), &
      registry_entry_t("linkage", new_linkage), &
      registry_entry_t("gear_geometry", new_gear_geometry), &
      registry_entry_t("planetary_synthesis", new_planetary_synthesis), &
      registry_entry_t("cam_profile", new_cam_profile)]
  end function registry_entries

  !> The kinds as a comma-separated list, for messages and --help.
  function known_kinds() result(text)
    character(len=:), allocatable :: text
    type(registry_entry_t), allocatable :: entries(:)
    integer :: i
    allocate (entries(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    entries = registry_entries()
    text = trim(entries(1)%name)
    do i = 2, size(entries)
      text = text//", "//trim(entries(i)%name)
    end do
  end function known_kinds

  !> A new mechanism of kind `name`; unallocated when the kind is unknown.
  subroutine create_mechanism(name, mech)
    !> Namelist group name.
    character(*), intent(in) :: name
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    type(registry_entry_t), allocatable :: entries(:)
    integer :: i
    allocate (entries(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    entries = registry_entries()
    do i = 1, size(entries)
      if (trim(entries(i)%name) == name) then
        call entries(i)%create(mech)
        return
      end if
    end do
  end subroutine create_mechanism

  !> The deck's first namelist group and a new mechanism of that kind; an input error (exit 2)
  !> naming the deck and the group when no kind has that name.
  subroutine deck_mechanism(source, group, mech, error)
    !> The deck.
    type(deck_source_t), intent(in) :: source
    !> Its first group's name.
    character(len=:), allocatable, intent(out) :: group
    !> The mechanism (unallocated on error).
    class(mechanism_t), allocatable, intent(out) :: mech
    type(error_t), allocatable, intent(out) :: error
    call read_group_name(source, group, error)
    if (allocated(error)) return
    call create_mechanism(group, mech)
    if (.not. allocated(mech)) call fatal_error(error, exit_input, source%path//": &"//group// &
      ": unknown mechanism (known: "//known_kinds()//")")
  end subroutine deck_mechanism

  !> The columns (name, unit, kind) of every kind's output, as its template deck gives them:
  !> what `kinetostat diff` knows about the columns of a CSV file. A kind whose template does
  !> not run adds nothing.
  subroutine known_columns(columns)
    !> The columns of all kinds, in registry order (names may repeat).
    type(column_t), allocatable, intent(out) :: columns(:)
    type(registry_entry_t), allocatable :: entries(:)
    class(mechanism_t), allocatable :: mech
    type(text_buffer_t) :: deck
    type(deck_source_t) :: source
    type(step_table_t) :: table
    type(error_t), allocatable :: error
    integer :: i
    allocate (columns(0))
    allocate (entries(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    entries = registry_entries()
    do i = 1, size(entries)
      call entries(i)%create(mech)
      deck = text_buffer_t()
      call mech%write_template(deck)
      call deck_source_from_text("template", deck%text(), source)
      call mech%read_deck(source, error)
      if (allocated(error)) cycle
      table = step_table_t()
      table%mechanism = trim(entries(i)%name)
      table%deck = "template"
      table%row_name = "step"
      table%driver = "M1"
      call mech%solve(table, error)
      if (allocated(error)) cycle
      columns = [columns, table%columns]
    end do
  end subroutine known_columns

end module kinetostat_registry
