!> The registry of mechanisms: one line per kind, (namelist group name, constructor).
!> The list of known kinds, `--help` and `template` come from it. Adding a mechanism = its
!> folder under src/ + one line in `registry_entries`.
module kinetostat_registry
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_pr3207_layout, only: new_pr3207
  use kinetostat_pr3050_layout, only: new_pr3050
  use kinetostat_sixbar_layout, only: new_sixbar
  use kinetostat_assur_layout, only: new_assur
  use kinetostat_gears_layout, only: new_gears
  use kinetostat_cam_layout, only: new_cam
  implicit none
  private
  public :: create_mechanism, known_kinds

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
    character(len=16) :: name = ""
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
      registry_entry_t("cam", new_cam)]
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

end module kinetostat_registry
