!> `&assur` decks: the capacities, the variables as written (the namelist's derived types)
!> and the validated deck and its load schedules (read by kinetostat_assur_deck).
module kinetostat_assur_deck_types
  use kinetostat_kinds, only: wp
  use kinetostat_load_table, only: max_table_points
  use kinetostat_deck, only: unset_real, unset_bits, title_chars, text_bytes, text_chars, angle_steps_t
  use kinetostat_vec2, only: magnitude
  use kinetostat_assur, only: assur_mech_t
  use kinetostat_assur_friction, only: pair_friction_t
  use kinetostat_dynamics_deck, only: dynamics_deck_t
  implicit none
  private
  public :: max_dyads, max_forces, max_moments, misfit_rel, max_table_points, group_name, joint_name_chars, &
    joint_name_length, joint_text_length, schedule_in_t, load_constant, load_window, &
    load_column, load_table, crank_index, resist_none, resist_moment, resist_force, resist_zero_rel, &
    load_schedule_t, assur_deck_t


  !> Capacity of the dyad list.
  integer, parameter :: max_dyads = 16
  !> Capacity of the external force list.
  integer, parameter :: max_forces = 16
  !> Capacity of the external moment list.
  integer, parameter :: max_moments = 16
  !> Global form: largest misfit of a given joint, relative to the dyad's size.
  real(wp), parameter :: misfit_rel = 1.0e-6_wp
  !> Unset logical marker is not available in namelists: logicals have plain defaults.
  character(*), parameter :: group_name = "assur"
  !> Longest joint name, characters; its storage and the length read, bytes (longer names
  !> are an error).
  integer, parameter :: joint_name_chars = 8, joint_name_length = text_bytes * joint_name_chars, &
    joint_text_length = text_bytes * text_chars

  !> `unset_real` for the default initialisation of the deck types below. Their variables
  !> must be declared in this module only: a NaN constant loses its payload in .mod files.
  real(wp), parameter :: unset = transfer(unset_bits, 1.0_wp)

  !> A per-step value: constant, angle window, or a column of `step_values`.
  type :: schedule_in_t
    !> Value (N or N*m): constant, or inside the window.
    real(wp) :: value = unset
    !> Value outside the window, default 0.
    real(wp) :: idle = unset
    !> Window [phi_on, phi_off] of crank angles (deg, absolute, not modulo 360).
    real(wp) :: phi_on = unset, phi_off = unset
    !> Column of `step_values` holding one value per step instead (a whole number).
    real(wp) :: column = unset
  end type schedule_in_t

  !> Load schedule: the same value at every step.
  integer, parameter :: load_constant = 1
  !> Load schedule: `value` inside a window of crank angles, `idle` outside.
  integer, parameter :: load_window = 2
  !> Load schedule: a column of the deck's step_values (one value per step).
  integer, parameter :: load_column = 3
  !> Load schedule: a table of values over the position of a link.
  integer, parameter :: load_table = 4
  !> Internal index of the crank (links: 0 frame, 1 crank, then the dyads' links).
  integer, parameter :: crank_index = 1
  !> Not a technological resistance: the value is applied as given.
  integer, parameter :: resist_none = 0
  !> A moment resisting its link's rotation.
  integer, parameter :: resist_moment = 1
  !> A force resisting its point's motion along the force's line.
  integer, parameter :: resist_force = 2
  !> A rate (rad/rad, or m/rad relative to the mechanism's size) at or below this counts as
  !> zero: the link stops, the resistance is zero at that step.
  real(wp), parameter :: resist_zero_rel = 1.0e-10_wp

  !> How a validated load (force magnitude or moment) gets its value at a step; the value
  !> of step k is assur_load_value (no per-step array is stored).
  type :: load_schedule_t
    !> load_constant, load_window, load_column or load_table.
    integer :: kind = load_constant
    !> Value, N or N*m: constant, or inside the window.
    real(wp) :: value = 0.0_wp
    !> Value outside the window, N or N*m.
    real(wp) :: idle = 0.0_wp
    !> Window [phi_on, phi_off] of crank angles, deg (absolute, not modulo 360).
    real(wp) :: phi_on = 0.0_wp, phi_off = 0.0_wp
    !> Column: step k's value is the deck's step_values(offset + k).
    integer :: offset = 0
    !> Table: positions of its points, deg (a link's angle) or m (a slider's stroke).
    real(wp), allocatable :: x(:)
    !> Table: values of its points, N or N*m.
    real(wp), allocatable :: v(:)
    !> Table: internal index of the link whose position is the abscissa.
    integer :: link = 0
    !> Table: the frame pair measuring that link's stroke (0: its angle).
    integer :: pair = 0
    !> Technological resistance: resist_none, resist_moment or resist_force (then the
    !> schedule gives the size and the motion of the loaded link the sign).
    integer :: resist = resist_none
    !> Resistance: internal index of the loaded link.
    integer :: resist_link = 0
    !> Resisting force: point of application in the link's coordinates, m.
    real(wp) :: resist_at(2) = 0.0_wp
    !> Resisting force: direction, rad (global, or relative to the link when follow).
    real(wp) :: resist_angle = 0.0_wp
    !> Resisting force: direction turns with the link.
    logical :: resist_follow = .false.
  end type load_schedule_t

  !> A validated `&assur` deck.
  type, extends(angle_steps_t) :: assur_deck_t
    !> Mechanism.
    type(assur_mech_t) :: mech
    !> Title (free text, at most title_chars characters).
    character(len=text_bytes * title_chars) :: title = ""
    !> Crank angles given as a list phi1(:), deg, elements 1..n (the namelist's read buffer,
    !> kept; not allocated: phi_start + (k - 1)*dphi). Step k's angle: assur_phi1_deg.
    real(wp), allocatable :: phi_list(:)
    !> Sign of the list's first move (+1 increasing, -1 decreasing; 0: the angles never
    !> change): the direction of the steps before it (see assur_omega1_steps).
    real(wp) :: first_move = 0.0_wp
    !> Whether phi_start was computed as the extreme position of the output link.
    logical :: start_extreme = .false.
    !> Whether the deck gave global points at the reference position (coordinates = 'global').
    logical :: global = .false.
    !> Reference position of the crank for the global form, deg.
    real(wp) :: phi_ref = 0.0_wp
    !> Direction of gravity, deg.
    real(wp) :: gravity_angle = -90.0_wp
    !> Constant crank speed (when not prescribed per step), rad/s.
    real(wp) :: omega1_const = 0.0_wp
    !> Whether omega1/eps1 were prescribed per step.
    logical :: prescribed = .false.
    !> Prescribed crank speed omega1_step, rad/s, elements 1..n (the read buffer, kept;
    !> allocated only when prescribed). Step k's speed: assur_omega1.
    real(wp), allocatable :: omega1_values(:)
    !> Prescribed crank acceleration eps1_step, rad/s^2, elements 1..n (as omega1_values).
    real(wp), allocatable :: eps1_values(:)
    !> The deck's step_values (columns of n values each), N or N*m (the read buffer, kept).
    real(wp), allocatable :: step_values(:)
    !> How each external force's magnitude (N) is given per step (see assur_load_value).
    type(load_schedule_t), allocatable :: force_load(:)
    !> How each external moment (N*m) is given per step (see assur_load_value).
    type(load_schedule_t), allocatable :: moment_load(:)
    !> Machine dynamics settings (dynamics, delta, j_rotor, j_flywheel).
    type(dynamics_deck_t) :: dyn
    !> Reporting frame angle of each pair (dyad pairs, then crank pin), rad.
    real(wp), allocatable :: pair_frame(:)
    !> Column name stem of each pair ("F21").
    character(len=16), allocatable :: pair_name(:)
    !> The name of every pair's joint on the sheets and in the kinematics columns (x_<name>),
    !> in the order of pair_name: the deck's `dyad(i)%joints` and `crank_joint`, J<pair>
    !> (J21 for F21) where not given.
    character(len=joint_name_length), allocatable :: joint_name(:)
    !> +1, or -1 where the report shows the reaction's opposite (inner pair on link b).
    real(wp), allocatable :: pair_sign(:)
    !> Angles in (-180, 180] instead of [0, 360).
    logical :: angles_signed = .false.
    !> CSV also carries the x, y components of every pair force.
    logical :: components = .true.
    !> Frame id, crank id.
    integer :: frame_id = 0, crank_id = 1
    !> Friction data of every pair (dyad pairs, then the crank pin).
    type(pair_friction_t), allocatable :: friction(:)
    !> Whether any pair has friction (otherwise the run is the frictionless one, byte for byte).
    logical :: friction_on = .false.
  end type assur_deck_t

end module kinetostat_assur_deck_types
