!> The general engine's linkage (`&linkage` decks) as data: its moving links, lower pairs,
!> drives, external forces and the units of its structural analysis (kinetostat_linkage
!> solves it; kinetostat_linkage_structure finds the units).
module kinetostat_linkage_types
  use kinetostat_kinds, only: wp
  implicit none
  private
  public :: linkage_t, linkage_link_t, linkage_pair_t, linkage_drive_t, linkage_force_t, linkage_unit_t
  public :: pair_r, pair_p

  !> Pair kind: turning (revolute) pair.
  integer, parameter :: pair_r = 1
  !> Pair kind: sliding (prismatic) pair.
  integer, parameter :: pair_p = 2

  !> A moving link: its reference point and mass data (global coordinates at the reference
  !> position).
  type :: linkage_link_t
    !> The deck's link number.
    integer :: id = 0
    !> Reference point (its first pair's point at the reference position), m.
    real(wp) :: c(2) = 0.0_wp
    !> Angle of the link's axis at the reference position (from its first pair's point to its
    !> second's), rad.
    real(wp) :: angle0 = 0.0_wp
    !> Mass, kg; moment of inertia about the centre of mass, kg*m^2.
    real(wp) :: m = 0.0_wp, j = 0.0_wp
    !> Centre of mass at the reference position, m.
    real(wp) :: s(2) = 0.0_wp
  end type linkage_link_t

  !> A lower pair between links a and b (0: the frame); F<a><b> is the force on a from b.
  type :: linkage_pair_t
    !> Name of the joint ("A", "T1"; at most 8 characters, Latin or Cyrillic letters: up
    !> to 2 bytes each in UTF-8).
    character(len=16) :: name = ""
    !> pair_r or pair_p.
    integer :: kind = pair_r
    !> Link indices (0 = frame, 1.. = moving links in deck order).
    integer :: a = 0, b = 0
    !> Sliding pair: the link that carries the guide (a or b); the other is the block.
    integer :: guide = 0
    !> The joint at the reference position (for P: a point of the guide line where the block
    !> is at the reference position), m.
    real(wp) :: at(2) = 0.0_wp
    !> Sliding pair: unit vector of the guide at the reference position.
    real(wp) :: u(2) = [1.0_wp, 0.0_wp]
  end type linkage_pair_t

  !> A drive on a pair: the relative angle of link a to link b of a turning pair, or the
  !> stroke of the block along the guide of a sliding pair.
  type :: linkage_drive_t
    !> The driven pair.
    integer :: pair = 0
    !> Value at the reference position: angle, rad (R), or stroke 0 m (P).
    real(wp) :: q_ref = 0.0_wp
  end type linkage_drive_t

  !> An external force of constant direction (global, or turning with its link).
  type :: linkage_force_t
    !> Loaded link index (1..n).
    integer :: link = 1
    !> Point of application at the reference position, m.
    real(wp) :: at(2) = 0.0_wp
    !> Unit vector of its direction at the reference position.
    real(wp) :: dir(2) = [1.0_wp, 0.0_wp]
    !> The direction turns with the link.
    logical :: follow = .false.
  end type linkage_force_t

  !> One unit of the structural analysis: an input unit (links moved by drives) or an Assur
  !> group, in the order the analysis found them.
  type :: linkage_unit_t
    !> Its link indices (1..n).
    integer, allocatable :: links(:)
    !> Its constraint rows (of J): the pairs among its links and between them and the links
    !> found before, with the drives on them.
    integer, allocatable :: rows(:)
    !> Class: 1 input unit, 2 dyad, 3 class-III group, 4 class-IV group, 0 not classified.
    integer :: class = 0
    !> Order (number of external pairs).
    integer :: order = 0
    !> Dyad kind (RRR, RRP, RPR, PRP, RPP), blank otherwise.
    character(len=3) :: kind = ""
    !> Text as the structure formula writes it ("II(2,3)").
    character(len=:), allocatable :: label
  end type linkage_unit_t

  !> A validated linkage.
  type :: linkage_t
    !> Moving links 1..n.
    type(linkage_link_t), allocatable :: links(:)
    !> Pairs in deck order.
    type(linkage_pair_t), allocatable :: pairs(:)
    !> Drives in deck order.
    type(linkage_drive_t), allocatable :: drives(:)
    !> External forces (magnitudes per step come from the deck).
    type(linkage_force_t), allocatable :: forces(:)
    !> Links of the external moments.
    integer, allocatable :: moment_link(:)
    !> Gravity acceleration vector, m/s^2.
    real(wp) :: gravity(2) = 0.0_wp
    !> Size of the linkage (largest distance between two of its pair points), m.
    real(wp) :: size = 1.0_wp
    !> Units of the structural analysis in the order found (inputs and groups).
    type(linkage_unit_t), allocatable :: units(:)
    !> The deck's frame number.
    integer :: frame_id = 0
  end type linkage_t

end module kinetostat_linkage_types
