!> The step table: everything a run reports, independent of the output format.
!> Columns (name, unit, kind of quantity), one row of `real(wp)` values per step (or per
!> stage), the INPUT DATA echo records, the self-check figures and the run's remarks.
!> Every mechanism fills one; every writer (CSV, legacy table, JSON) reads one.
module kinetostat_step_table
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, rad_to_deg
  use kinetostat_error, only: error_t, out_of_memory
  use kinetostat_text, only: int_str, int64_str, upper
  use kinetostat_run_tally, only: run_tally_t, dynamics_figures_t, flywheel_disc, running_max_t, column_tally_t, edge_point_t
  use kinetostat_labels, only: label, lang_ru
  use kinetostat_noise, only: force_components
  implicit none
  private
  public :: step_table_t, column_t, column, echo_record_t, echo_cursor_t, remark_t, column_tally_t, edge_point_t, &
    student_t, step_span, worst_row, lack_block_memory
  public :: col_input_angle, col_force, col_force_angle, col_component, col_moment, col_length, &
    col_flag, col_count, col_ratio, col_other, column_kind_names
  public :: echo_real_kind, echo_int_kind, echo_logical_kind, echo_array_kind, echo_text_kind, &
    echo_heading_kind, echo_line_kind

  !> The DYNAMICS block's note on the flywheel's disc (a key of the labels' dictionary).
  character(*), parameter :: flywheel_disc_note = "a disc: J_flywheel = m D^2/8, m = density pi D^2 b/4, "// &
    "b = width_ratio D"
  !> The note when the machine has no flywheel.
  character(*), parameter :: flywheel_none_note = "no flywheel: J_flywheel = 0"

  !> Column kind: the input coordinate of the step (crank angle, cam angle), deg.
  integer, parameter :: col_input_angle = 1
  !> Column kind: magnitude of a pair force, N.
  integer, parameter :: col_force = 2
  !> Column kind: angle of a pair force, deg.
  integer, parameter :: col_force_angle = 3
  !> Column kind: a signed force or force component, N.
  integer, parameter :: col_component = 4
  !> Column kind: a moment (torque), N*m.
  integer, parameter :: col_moment = 5
  !> Column kind: a length or displacement, m (or mm where the unit says so).
  integer, parameter :: col_length = 6
  !> Column kind: a 0/1 flag (written as an integer).
  integer, parameter :: col_flag = 7
  !> Column kind: a whole number such as a stage index or a tooth count (written as an integer).
  integer, parameter :: col_count = 8
  !> Column kind: a dimensionless ratio.
  integer, parameter :: col_ratio = 9
  !> Column kind: anything else (angles of links, speeds, ...).
  integer, parameter :: col_other = 10
  !> Names of the column kinds, for JSON and the docs.
  character(*), parameter :: column_kind_names(*) = [character(len=13) :: "input_angle", "force", &
    "force_angle", "component", "moment", "length", "flag", "count", "ratio", "other"]

  !> Echo record: a real deck value.
  integer, parameter :: echo_real_kind = 1
  !> Echo record: an integer deck value.
  integer, parameter :: echo_int_kind = 2
  !> Echo record: a logical deck value.
  integer, parameter :: echo_logical_kind = 3
  !> Echo record: an array of reals.
  integer, parameter :: echo_array_kind = 4
  !> Echo record: a text value (e.g. a layout name).
  integer, parameter :: echo_text_kind = 5
  !> Echo record: a sub-heading (blank line, then the text).
  integer, parameter :: echo_heading_kind = 6
  !> Echo record: a line of text printed as it is (a summary line of a group of values).
  integer, parameter :: echo_line_kind = 7

  !> One output column, declared once (see `column`): its name and unit for CSV, JSON and
  !> npy, its kind, and its heading and unit in the legacy table in English and Russian.
  type :: column_t
    !> Name as in the CSV header (e.g. "F16").
    character(len=:), allocatable :: name
    !> SI unit ("N", "deg", "N*m", "" for dimensionless).
    character(len=:), allocatable :: unit
    !> The unit in Russian as the 1991 printouts write it ("Н", "Н*м", "град"); not allocated
    !> when nobody declared it (the labels' dictionary has no translation of `unit`).
    character(len=:), allocatable :: unit_ru
    !> Heading of the column in the legacy table ("PHI1", "F16G"); "" when the legacy table
    !> does not print the column under a heading of its own.
    character(len=:), allocatable :: heading
    !> The heading in Russian (the printouts' identifiers are the same: `heading` by default).
    character(len=:), allocatable :: heading_ru
    !> The unit under the heading when the legacy table shows another than `unit` ("deg/x1":
    !> the angle's axis), in English and Russian; not allocated: `unit`, `unit_ru`.
    character(len=:), allocatable :: heading_unit, heading_unit_ru
    !> Kind of quantity (col_*).
    integer :: kind = col_other
    !> False for a column shown only by the legacy table and JSON (not part of the CSV).
    logical :: csv = .true.
    !> True for a kinematics column (positions, link angles and speeds, accelerations, force
    !> components): always in the table, shown by CSV and JSON only when asked (--kinematics),
    !> never by the legacy table.
    logical :: kinematic = .false.
    !> Force component columns: angle of the x axis of the frame the components are given in,
    !> measured in the mechanism's position frame, deg (0 when they are the same frame).
    real(wp) :: frame_angle = 0.0_wp
    !> True for a pair force component in the moving axes of the link it acts on (<F>_along,
    !> <F>_across): always in the table, shown by CSV and JSON only with --frame link.
    logical :: link_axes = .false.
    !> Link-axes columns: the label of that link (its angle is the kinematics column phi<label>).
    character(len=:), allocatable :: frame_link
    !> True for a column with no value at a void row (see step_table_t%void_flags): CSV
    !> writes an empty field there, JSON null, and the summary leaves the row out.
    logical :: voidable = .false.
  end type column_t

  !> The student's header of a run (--student, --group, --variant): who ran the deck and
  !> when, for the legacy table's student line and the sheets' title blocks.
  type :: student_t
    !> Surname, group and variant ("-" when not given).
    character(len=:), allocatable :: name, group, variant
    !> Date and time of the run ("25.11.2026 18:31").
    character(len=:), allocatable :: stamp
  end type student_t

  !> One remark of a run for the user (a warning on stderr, in JSON).
  type :: remark_t
    !> The text, without "kinetostat: warning: <deck>: ".
    character(len=:), allocatable :: text
  end type remark_t

  !> One INPUT DATA echo record.
  type :: echo_record_t
    !> echo_*_kind.
    integer :: kind = echo_real_kind
    !> Variable name as printed (e.g. "L_AB"), or the text of a heading/line.
    character(len=:), allocatable :: name
    !> Unit text ("m", "kg", ...).
    character(len=:), allocatable :: unit
    !> Real value(s): one for echo_real_kind, all for echo_array_kind; with `run_end`, the
    !> value of each run of equal values instead (an array of 10^6 equal values is one).
    real(wp), allocatable :: values(:)
    !> Runs of equal values of an array: run r ends at value run_end(r) and has the value
    !> values(r). Not allocated when the values are kept one by one.
    integer, allocatable :: run_end(:)
    !> Integer value (echo_int_kind).
    integer :: int_value = 0
    !> Logical value (echo_logical_kind).
    logical :: logical_value = .false.
    !> Text value (echo_text_kind).
    character(len=:), allocatable :: text
    !> True when the value came from --set (marked in the INPUT DATA echo).
    logical :: overridden = .false.
  contains
    procedure :: value_count
    procedure :: get_values
  end type echo_record_t

  !> Values of an echoed array a writer formats at a time (the output is drained between
  !> such chunks, so a deck's 10^6 per-step values never become one piece of text).
  integer, parameter :: echo_chunk_values = 65536

  !> Where a writer is in the INPUT DATA echo: it writes up to a chunk of array values, then
  !> returns for the output to be drained, and goes on from there when called again.
  type :: echo_cursor_t
    !> Record being written (0: the lines before the first record are not written yet).
    integer :: record = 0
    !> Values of that record's array already written.
    integer :: value = 0
    !> Array values per chunk (0: echo_chunk_values; tests make it small).
    integer :: chunk = 0
    !> True when the whole head is written.
    logical :: done = .false.
  contains
    procedure :: take
  end type echo_cursor_t

  !> All results of a run.
  type :: step_table_t
    !> Mechanism kind: the namelist group name ("pr3207").
    character(len=:), allocatable :: mechanism
    !> Deck path as given (for titles and messages).
    character(len=:), allocatable :: deck
    !> A line printed under the deck line of the legacy table (the deck's own title), if any.
    character(len=:), allocatable :: subtitle
    !> The student's header (--student, --group, --variant); unallocated when not asked for.
    type(student_t), allocatable :: student
    !> What one row is, for messages ("step", "stage").
    character(len=:), allocatable :: row_name
    !> Index of the column holding the input coordinate (0 when there is none).
    integer :: input_column = 0
    !> Column put_kinematic set last (a step puts its kinematics in the same order every
    !> time, so the next one is looked for after it before searching all columns).
    integer :: last_kinematic = 0
    !> Row 1 of kinematics columns added during row 1 and not yet in `rows` (a table of many
    !> rows grows by all of them at once, when row 2 arrives or finish_columns is called,
    !> instead of copying every row once per new column).
    real(wp), allocatable :: pending(:)
    !> Whether `solve` adds the kinematics and link-axes columns (true by default; the run
    !> pipeline turns it off when no output of the run shows them).
    logical :: kinematics_wanted = .true.
    !> Whether `solve` computes the pair forces' angle columns (true by default; the run
    !> pipeline turns it off when neither the output nor the caller reads them: a plain
    !> --format summary, a sweep's variant; such a run's angle cells are 0).
    logical :: force_angles_wanted = .true.
    !> Whether an output of the run reads the columns' figures over the run (true by
    !> default: the summaries, the legacy table's SUMMARY block, the sheets). The run
    !> pipeline turns it off for CSV, npy and JSON, which show the rows and the self-check
    !> only: the run's tally then keeps no more than the coarse-step warning reads (see
    !> `tallied`).
    logical :: summaries_wanted = .true.
    !> The columns.
    type(column_t), allocatable :: columns(:)
    !> Values, rows(column, row).
    real(wp), allocatable :: rows(:, :)
    !> INPUT DATA echo records, in print order.
    type(echo_record_t), allocatable :: echo(:)
    !> Number of echo records in use.
    integer :: echo_count = 0
    !> Whether the run has a self-check.
    logical :: has_selfcheck = .true.
    !> The figures a kind's solve notes for the block it solved (self-check maxima, drive
    !> deviation, force peaks, sums); the run pipeline clears it before each block.
    type(run_tally_t) :: block_tally
    !> The same figures over the run so far, and per column its extremes, sums and trapezoid
    !> sums in row order: the run pipeline merges every block's into it (kinetostat_run's
    !> tally_block: merge_tally, then kinetostat_summary's tally_rows). Summaries, footers,
    !> the self-check and JSON read this one.
    type(run_tally_t) :: run_tally
    !> Name of the driving quantity ("M1", "F2", ...).
    character(len=:), allocatable :: driver
    !> Footer label of the residual line (default: all links and steps).
    character(len=:), allocatable :: residual_label
    !> Footer label of the mismatch line (default: driver vs power balance).
    character(len=:), allocatable :: mismatch_label
    !> The run's warnings (stderr unless --quiet, exit 4 with --strict), in order.
    type(remark_t), allocatable :: warnings(:)
    !> load_changes(k): an applied load (a cutting force, a resistance) has another value at
    !> row k than at row k-1 (row 1: than at the last row, used when the run spans a turn).
    !> Not allocated when the mechanism reports no switching loads.
    logical, allocatable :: load_changes(:)
    !> Index of the column of the coordinate along which the driver does work (a length, m);
    !> 0: the input angle (deg) when the driver is a moment.
    integer :: work_column = 0
    !> The run's overrides as given ("l_ab=0.12"), blank-padded; not allocated without any.
    character(len=:), allocatable :: overrides(:)
    !> Heading of the summary block (results of the whole run, e.g. work and efficiency).
    character(len=:), allocatable :: summary_heading
    !> Summary records (real values and lines of text), printed after RESULTS; none by default.
    type(echo_record_t), allocatable :: summary(:)
    !> The machine dynamics figures of the run (the DYNAMICS block, JSON "dynamics": M_d, the
    !> flywheel, the speed's extremes, delta); `present` false without a steady cycle. The
    !> force peaks the block goes on with are in the run tally (dynamics_records lists both).
    type(dynamics_figures_t) :: dynamics
    !> The run reports the pair forces in link axes (--frame link; the legacy table prints the
    !> link-axes columns instead of magnitudes and angles, CSV and JSON add them).
    logical :: link_frame = .false.
    !> CSV and JSON show the kinematics columns (--kinematics).
    logical :: kinematics_shown = .false.
    !> The sheets' title block: the document's designation (графа 2 and 26; not allocated:
    !> empty), the sheet's number and the number of sheets (kinetostat sheets --sheet-numbers).
    character(len=:), allocatable :: designation
    integer :: sheet_number = 1, sheet_count = 1
    !> Block asked of `solve` by the run pipeline: first and last step (0: every step at once).
    integer :: block_first = 0
    !> Last step of the block asked (0: every step).
    integer :: block_last = 0
    !> `rows` holds the run's rows row_offset+1 .. row_offset+row_count().
    integer :: row_offset = 0
    !> Number of rows of the whole run (0 until a mechanism's solve says so).
    integer :: total_rows = 0
    !> The run's row numbers of the rows held, when they are a selection of the run's rows
    !> (kinetostat_row_keeper: the row of --at K, a long run's extremes for the SVG sheet);
    !> not allocated: the rows are row_offset+1 .. row_offset+row_count().
    integer, allocatable :: row_numbers(:)
    !> What did not fit in memory, when an allocation of the table failed ("the echo of
    !> OMEGA3 (1000000 values) (8000000 bytes)"; the run pipeline stops with exit 2).
    character(len=:), allocatable :: no_room
    !> State a mechanism's solver takes from one block to the next (the last step's pose, a
    !> start for the next step's iteration; not a figure of the run: those go to
    !> block_tally); its own layout, not allocated before the first block.
    real(wp), allocatable :: carry(:)
    !> Flag columns (0/1) that make a row void where one is nonzero: the voidable columns
    !> have no value there (a cam follower jammed or off the cam). Unallocated: none.
    integer, allocatable :: void_flags(:)
    !> Why a row is void, for the summary ("jammed or lost contact").
    character(len=:), allocatable :: void_reason
    !> The run is one record (a design's figures, not steps): --format summary writes its
    !> values under the columns' own names.
    logical :: single_record = .false.
  contains
    procedure :: block_range
    procedure :: first_block
    procedure :: last_block
    procedure :: add_column
    procedure :: put_point
    procedure :: put_link
    procedure :: put_acceleration
    procedure :: put_velocity
    procedure :: put_components
    procedure :: put_pair_components
    procedure :: put_link_axes
    procedure :: shows
    procedure :: tallied
    procedure :: finish_columns
    procedure :: set_columns
    procedure :: declare_columns
    procedure :: declare_record
    procedure :: column_index
    procedure :: dynamics_records
    procedure :: shaft_inertia
    procedure :: allocate_rows
    procedure :: row_count
    procedure :: lack_room
    procedure :: run_row
    procedure :: run_rows
    procedure :: add_warning
    procedure :: note_load
    procedure :: warning_count
    procedure :: is_whole
    procedure :: is_void
    procedure :: void_cell
    procedure :: set_selfcheck
    procedure :: set_selfcheck_rows
    procedure :: echo_real => echo_value
    procedure :: echo_int => echo_value
    procedure :: echo_logical => echo_value
    procedure :: echo_array
    procedure :: echo_text
    procedure :: echo_heading
    procedure :: echo_line
    procedure :: summary_real
    procedure :: summary_line
  end type step_table_t

contains

  !> The steps `solve` computes now, of a run of `n` steps: the block the run pipeline asks
  !> for (block_first .. block_last, cut at n), or all of them when it asks for none. Sets
  !> total_rows and row_offset; the rows of the block are then rows 1 .. last - first + 1.
  pure subroutine block_range(self, n, first, last)
    class(step_table_t), intent(inout) :: self
    !> Number of steps of the whole run.
    integer, intent(in) :: n
    !> First step to compute now.
    integer, intent(out) :: first
    !> Last step to compute now.
    integer, intent(out) :: last
    first = 1
    last = n
    if (self%block_last > 0) then
      first = max(1, self%block_first)
      last = min(n, self%block_last)
    end if
    self%total_rows = n
    self%row_offset = first - 1
  end subroutine block_range

  !> Whether the rows now in the table are the first of the run (the columns, the INPUT
  !> DATA echo and the deck's loads are set then, once).
  pure logical function first_block(self)
    class(step_table_t), intent(in) :: self
    first_block = self%row_offset == 0
  end function first_block

  !> Steps k1 .. k2 a kernel loop computes: first .. last when given, else 1 .. n.
  pure subroutine step_span(n, k1, k2, first, last)
    !> Steps of the whole run.
    integer, intent(in) :: n
    !> First step to compute.
    integer, intent(out) :: k1
    !> Last step to compute.
    integer, intent(out) :: k2
    !> The block's first and last step (table%block_range), if only a block is asked for.
    integer, intent(in), optional :: first, last
    k1 = 1
    k2 = n
    if (present(first)) k1 = first
    if (present(last)) k2 = last
  end subroutine step_span

  !> The error of a block's results that do not fit in memory.
  pure subroutine lack_block_memory(error, steps, step_bytes, what)
    !> The error to create.
    type(error_t), allocatable, intent(out) :: error
    !> Steps of the block.
    integer, intent(in) :: steps
    !> Bytes of one step's results.
    integer(int64), intent(in) :: step_bytes
    !> What the block holds (default "results": "the results of a block of N steps").
    character(*), intent(in), optional :: what
    if (present(what)) then
      call out_of_memory(error, "the "//what//" of a block of "//int_str(steps)//" steps", steps * step_bytes)
    else
      call out_of_memory(error, "the results of a block of "//int_str(steps)//" steps", steps * step_bytes)
    end if
  end subroutine lack_block_memory

  !> Whether the rows now in the table end the run (the footers are written then).
  pure logical function last_block(self)
    class(step_table_t), intent(in) :: self
    last_block = self%row_offset + self%row_count() >= self%total_rows
  end function last_block

  !> A column's declaration: its name and unit (CSV, JSON, npy), kind, and how the legacy
  !> table heads it in English and Russian. The Russian unit is the labels' dictionary's
  !> translation of `unit` unless given; the Russian heading is `heading` unless given.
  pure function column(name, unit, kind, heading, heading_ru, unit_ru, heading_unit, heading_unit_ru, csv, voidable) &
    result(c)
    !> Column name (CSV header, JSON key).
    character(*), intent(in) :: name
    !> SI unit ("" when dimensionless).
    character(*), intent(in) :: unit
    !> col_* kind.
    integer, intent(in) :: kind
    !> Heading in the legacy table (default "": not printed under a heading of its own).
    character(*), intent(in), optional :: heading
    !> Heading in Russian (default `heading`).
    character(*), intent(in), optional :: heading_ru
    !> Unit in Russian (default: the labels' dictionary's translation of `unit`).
    character(*), intent(in), optional :: unit_ru
    !> Unit under the heading when not `unit` ("deg/x1"), and in Russian.
    character(*), intent(in), optional :: heading_unit, heading_unit_ru
    !> Whether the CSV shows it (default true).
    logical, intent(in), optional :: csv
    !> No value at a void row (default false; see column_t%voidable).
    logical, intent(in), optional :: voidable
    type(column_t) :: c
    c%name = name
    c%unit = unit
    c%kind = kind
    if (present(unit_ru)) then
      c%unit_ru = unit_ru
    else
      call russian_unit(c)
    end if
    c%heading = ""
    if (present(heading)) c%heading = heading
    c%heading_ru = c%heading
    if (present(heading_ru)) c%heading_ru = heading_ru
    if (present(heading_unit)) c%heading_unit = heading_unit
    if (present(heading_unit_ru)) c%heading_unit_ru = heading_unit_ru
    if (present(csv)) c%csv = csv
    if (present(voidable)) c%voidable = voidable
  end function column

  !> The Russian unit of column `c` from the labels' dictionary (not allocated when it has no
  !> translation of a unit with Latin letters).
  pure subroutine russian_unit(c)
    type(column_t), intent(inout) :: c
    character(len=:), allocatable :: text
    integer :: i
    text = label(c%unit, lang_ru)
    if (text == c%unit) then
      do i = 1, len(text)
        if (index("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ", text(i:i)) > 0) return
      end do
    end if
    c%unit_ru = text
  end subroutine russian_unit

  !> Append declared columns (see `column`), in order.
  pure subroutine declare_columns(self, columns)
    class(step_table_t), intent(inout) :: self
    !> The declarations.
    type(column_t), intent(in) :: columns(:)
    if (.not. allocated(self%columns)) allocate (self%columns(0))
    self%columns = [self%columns, columns]
  end subroutine declare_columns

  !> Declare a design kind's one record of named values (single_record): its columns, what
  !> the row is ("pair", "train") and the figure the run is about (driver); its row allocated.
  pure subroutine declare_record(self, columns, row_name, driver)
    class(step_table_t), intent(inout) :: self
    !> The record's columns.
    type(column_t), intent(in) :: columns(:)
    !> What the row is.
    character(*), intent(in) :: row_name
    !> The column the run is about.
    character(*), intent(in) :: driver
    call self%declare_columns(columns)
    self%row_name = row_name
    self%driver = driver
    self%single_record = .true.
    call self%allocate_rows(1)
  end subroutine declare_record

  !> Append one column.
  pure subroutine add_column(self, name, unit, kind, csv)
    class(step_table_t), intent(inout) :: self
    !> Column name.
    character(*), intent(in) :: name
    !> Unit text.
    character(*), intent(in) :: unit
    !> col_* kind.
    integer, intent(in) :: kind
    !> Whether the CSV shows it (default true).
    logical, intent(in), optional :: csv
    call self%declare_columns([column(name, unit, kind, csv=csv)])
  end subroutine add_column

  !> Kinematics: the position x_<point>, y_<point> (m) of a named point (joint, centre of mass)
  !> in row `k`; the columns are created on first use.
  pure subroutine put_point(self, k, point, p)
    class(step_table_t), intent(inout) :: self
    !> Row.
    integer, intent(in) :: k
    !> Point name as the manual names it ("A", "S3").
    character(*), intent(in) :: point
    !> Position, m.
    real(wp), intent(in) :: p(2)
    call put_kinematic(self, k, "x_", point, "m", col_length, p(1))
    call put_kinematic(self, k, "y_", point, "m", col_length, p(2))
  end subroutine put_point

  !> Kinematics: angle phi<link> (deg), angular velocity omega<link> (rad/s) and acceleration
  !> eps<link> (rad/s^2) of a link in row `k`. A column the mechanism reports already (the
  !> input angle phi1) keeps its value.
  pure subroutine put_link(self, k, link, phi, omega, eps)
    class(step_table_t), intent(inout) :: self
    !> Row.
    integer, intent(in) :: k
    !> Link number as the manual names it ("3").
    character(*), intent(in) :: link
    !> Angle, rad.
    real(wp), intent(in) :: phi
    !> Angular velocity, rad/s, counter-clockwise positive.
    real(wp), intent(in) :: omega
    !> Angular acceleration, rad/s^2.
    real(wp), intent(in) :: eps
    call put_kinematic(self, k, "phi", link, "deg", col_other, phi * rad_to_deg)
    call put_kinematic(self, k, "omega", link, "rad/s", col_other, omega)
    call put_kinematic(self, k, "eps", link, "rad/s^2", col_other, eps)
  end subroutine put_link

  !> Kinematics: velocity vx_<point>, vy_<point> (m/s) of a named point in row `k`.
  pure subroutine put_velocity(self, k, point, v)
    class(step_table_t), intent(inout) :: self
    !> Row.
    integer, intent(in) :: k
    !> Point name ("B", "S3").
    character(*), intent(in) :: point
    !> Velocity, m/s.
    real(wp), intent(in) :: v(2)
    call put_kinematic(self, k, "vx_", point, "m/s", col_other, v(1))
    call put_kinematic(self, k, "vy_", point, "m/s", col_other, v(2))
  end subroutine put_velocity

  !> Kinematics: acceleration ax_<point>, ay_<point> (m/s^2) of a named point in row `k`.
  pure subroutine put_acceleration(self, k, point, a)
    class(step_table_t), intent(inout) :: self
    !> Row.
    integer, intent(in) :: k
    !> Point name ("S3").
    character(*), intent(in) :: point
    !> Acceleration, m/s^2.
    real(wp), intent(in) :: a(2)
    call put_kinematic(self, k, "ax_", point, "m/s^2", col_other, a(1))
    call put_kinematic(self, k, "ay_", point, "m/s^2", col_other, a(2))
  end subroutine put_acceleration

  !> Kinematics: components <force>_x, <force>_y (N) of a pair force in row `k`, in the frame
  !> of the table's angle column <force>G, whose x axis lies at `frame_angle` (deg) in the
  !> position frame.
  pure subroutine put_components(self, k, force, f, frame_angle)
    class(step_table_t), intent(inout) :: self
    !> Row.
    integer, intent(in) :: k
    !> Force name ("F21").
    character(*), intent(in) :: force
    !> Components, N.
    real(wp), intent(in) :: f(2)
    !> Angle of the components' frame in the position frame, deg.
    real(wp), intent(in) :: frame_angle
    call put_kinematic(self, k, force, "_x", "N", col_component, f(1), frame_angle)
    call put_kinematic(self, k, force, "_y", "N", col_component, f(2), frame_angle)
  end subroutine put_components

  !> Kinematics: the components of every pair force names(i) = f(:, i) in row `k` (see
  !> put_components), those at or below the roundoff `floor` as 0 (force_components).
  pure subroutine put_pair_components(self, k, names, f, floor, frame_angles)
    class(step_table_t), intent(inout) :: self
    !> Row.
    integer, intent(in) :: k
    !> Force names ("F21"; trailing blanks dropped).
    character(*), intent(in) :: names(:)
    !> The forces, N: f(:, i) is force i's.
    real(wp), intent(in) :: f(:, :)
    !> Roundoff floor, N (see noise_floor).
    real(wp), intent(in) :: floor
    !> Angle of each force's frame in the position frame, deg (default: 0, the position frame).
    real(wp), intent(in), optional :: frame_angles(:)
    real(wp) :: frame_angle
    integer :: i
    frame_angle = 0.0_wp
    do i = 1, size(names)
      if (present(frame_angles)) frame_angle = frame_angles(i)
      call self%put_components(k, trim(names(i)), force_components(f(:, i), floor), frame_angle)
    end do
  end subroutine put_pair_components

  !> Link axes (--frame link): components <force>_along, <force>_across (N) of a pair force
  !> in row `k` in the moving axes of the link it acts on (x along the link's x axis).
  pure subroutine put_link_axes(self, k, force, f, link)
    class(step_table_t), intent(inout) :: self
    !> Row.
    integer, intent(in) :: k
    !> Force name ("F21").
    character(*), intent(in) :: force
    !> Components (along, across), N.
    real(wp), intent(in) :: f(2)
    !> Label of the link the force acts on ("2"; its angle column is phi<link>).
    character(*), intent(in) :: link
    call put_kinematic(self, k, force, "_along", "N", col_component, f(1), link=link)
    call put_kinematic(self, k, force, "_across", "N", col_component, f(2), link=link)
  end subroutine put_link_axes

  !> Set the value of kinematics column `prefix//suffix` in row `k`, appending the column
  !> (zero in every row) on first use; a column of that name that is not a kinematics column
  !> (one the mechanism reports anyway) is left as it is. With `link` the column is a
  !> link-axes column of that link instead. The name comes in two parts so that no string is
  !> built per value (only when a column is added).
  pure subroutine put_kinematic(self, k, prefix, suffix, unit, kind, value, frame_angle, link)
    type(step_table_t), intent(inout) :: self
    integer, intent(in) :: k
    character(*), intent(in) :: prefix, suffix, unit
    integer, intent(in) :: kind
    real(wp), intent(in) :: value
    real(wp), intent(in), optional :: frame_angle
    character(*), intent(in), optional :: link
    type(column_t) :: c
    real(wp), allocatable :: grown(:, :)
    !> The new column's legacy heading and Russian unit, where it has them.
    character(len=:), allocatable :: heading, unit_ru
    integer :: i, j, stat
    ! out of memory already (kinetostat_run stops the run): nothing more is kept
    if (allocated(self%no_room)) return
    if (allocated(self%pending) .and. k /= 1) call self%finish_columns()
    if (allocated(self%no_room)) return
    i = self%last_kinematic + 1
    if (i > size(self%columns)) then
      i = 0
    else if (.not. named(self%columns(i)%name)) then
      i = 0
    end if
    if (i == 0) then
      do i = size(self%columns), 1, -1
        if (named(self%columns(i)%name)) exit
      end do
    end if
    if (i == 0) then
      ! the Russian unit of an earlier column added here with the same unit (the labels'
      ! dictionary is looked up once per unit, not once per column)
      do j = size(self%columns), 1, -1
        if (.not. (self%columns(j)%kinematic .or. self%columns(j)%link_axes)) cycle
        if (.not. allocated(self%columns(j)%unit_ru)) cycle
        if (self%columns(j)%unit == unit) exit
      end do
      if (j > 0) unit_ru = self%columns(j)%unit_ru
      ! a link-axes column is headed in the legacy table: F21_ALONG, F21_ACROSS
      if (present(link)) heading = prefix//upper(suffix)
      ! (an unallocated heading or unit_ru is an absent argument: column's defaults)
      c = column(prefix//suffix, unit, kind, heading=heading, unit_ru=unit_ru)
      c%kinematic = .not. present(link)
      c%link_axes = present(link)
      if (present(link)) c%frame_link = link
      if (present(frame_angle)) c%frame_angle = frame_angle
      call append_column(self%columns, c)
      i = size(self%columns)
      if (k == 1 .and. size(self%rows, 2) > 1) then
        if (.not. allocated(self%pending)) allocate (self%pending(0))
        self%pending = [self%pending, 0.0_wp]
      else
        call self%finish_columns()
        if (allocated(self%no_room)) return
        allocate (grown(i, size(self%rows, 2)), source=0.0_wp, stat=stat)
        if (stat /= 0) then
          call self%lack_room("the kinematics columns of a block of "//int_str(size(self%rows, 2))//" steps", &
            8_int64 * i * size(self%rows, 2))
          return
        end if
        grown(1:i - 1, :) = self%rows
        call move_alloc(grown, self%rows)
      end if
    end if
    if (self%columns(i)%kinematic .or. self%columns(i)%link_axes) then
      if (i > size(self%rows, 1)) then
        self%pending(i - size(self%rows, 1)) = value + 0.0_wp
      else
        self%rows(i, k) = value + 0.0_wp
      end if
    end if
    self%last_kinematic = i
  contains
    !> Whether `name` is prefix//suffix.
    pure logical function named(name)
      character(*), intent(in) :: name
      named = .false.
      if (len(name) /= len(prefix) + len(suffix)) return
      named = name(1:len(prefix)) == prefix .and. name(len(prefix) + 1:) == suffix
    end function named
  end subroutine put_kinematic

  !> Append column `c` (left empty) to `columns`: the columns there are moved into the grown
  !> list, not copied (a copy would allocate every text of every column again: a row's
  !> kinematics columns, added one at a time, would copy the list once per column).
  pure subroutine append_column(columns, c)
    !> The columns (grown by one).
    type(column_t), allocatable, intent(inout) :: columns(:)
    !> The new column.
    type(column_t), intent(inout) :: c
    type(column_t), allocatable :: grown(:)
    integer :: i, n
    n = size(columns)
    allocate (grown(n + 1))
    do i = 1, n
      call move_column(columns(i), grown(i))
    end do
    call move_column(c, grown(n + 1))
    call move_alloc(grown, columns)
  end subroutine append_column

  !> Column `from` into `to` (every component of column_t; the texts moved, `from`'s left
  !> unallocated).
  pure subroutine move_column(from, to)
    !> The column moved.
    type(column_t), intent(inout) :: from
    !> Where it goes (a column of a new list).
    type(column_t), intent(inout) :: to
    call move_text(from%name, to%name)
    call move_text(from%unit, to%unit)
    call move_text(from%unit_ru, to%unit_ru)
    call move_text(from%heading, to%heading)
    call move_text(from%heading_ru, to%heading_ru)
    call move_text(from%heading_unit, to%heading_unit)
    call move_text(from%heading_unit_ru, to%heading_unit_ru)
    call move_text(from%frame_link, to%frame_link)
    to%kind = from%kind
    to%csv = from%csv
    to%kinematic = from%kinematic
    to%frame_angle = from%frame_angle
    to%link_axes = from%link_axes
    to%voidable = from%voidable
  end subroutine move_column

  !> move_alloc of a deferred-length text (allocated or not).
  pure subroutine move_text(from, to)
    character(len=:), allocatable, intent(inout) :: from, to
    if (allocated(from)) call move_alloc(from, to)
  end subroutine move_text

  !> Give `rows` every column added so far (the pending kinematics columns of row 1, zero in
  !> the other rows); the run pipeline calls it after the mechanism's solve.
  pure subroutine finish_columns(self)
    class(step_table_t), intent(inout) :: self
    real(wp), allocatable :: grown(:, :)
    integer :: done, stat
    if (.not. allocated(self%pending)) return
    done = size(self%rows, 1)
    allocate (grown(size(self%columns), size(self%rows, 2)), source=0.0_wp, stat=stat)
    if (stat /= 0) then
      call self%lack_room("the kinematics columns of a block of "//int_str(size(self%rows, 2))//" steps", &
        8_int64 * size(self%columns) * size(self%rows, 2))
      return
    end if
    grown(1:done, :) = self%rows
    grown(done + 1:, 1) = self%pending
    call move_alloc(grown, self%rows)
    deallocate (self%pending)
  end subroutine finish_columns

  !> Whether CSV and JSON show column `c`: kinematics columns only with kinematics_shown,
  !> link-axes columns only with link_frame.
  pure logical function shows(self, c)
    class(step_table_t), intent(in) :: self
    !> Column index.
    integer, intent(in) :: c
    if (self%columns(c)%link_axes) then
      shows = self%link_frame
    else
      shows = self%kinematics_shown .or. .not. self%columns(c)%kinematic
    end if
  end function shows

  !> Whether the run's tally keeps column `c`'s extremes, sums and trapezoid sums
  !> (kinetostat_summary's tally_rows): every column whose figures an output or a check of
  !> the run reads (the summaries, the table's SUMMARY block, the driver's extremes and mean,
  !> the overflow guard, the coarse-step warning), that is all but the input coordinate (its
  !> first and last values and largest step are the run's own figures), a force's angle (a
  !> direction has no extremes or mean) and a kinematics column CSV and JSON do not show.
  !> Without summaries_wanted, only the force columns of a run with switching loads (the
  !> coarse-step warning reads their peaks).
  pure logical function tallied(self, c)
    class(step_table_t), intent(in) :: self
    !> Column index.
    integer, intent(in) :: c
    if (self%summaries_wanted) then
      tallied = c /= self%input_column .and. self%columns(c)%kind /= col_force_angle .and. &
        (self%kinematics_shown .or. .not. self%columns(c)%kinematic)
    else
      tallied = self%columns(c)%kind == col_force .and. self%columns(c)%csv .and. allocated(self%load_changes)
    end if
  end function tallied

  !> Set all columns at once from parallel lists of names, units and kinds.
  pure subroutine set_columns(self, names, units, kinds)
    class(step_table_t), intent(inout) :: self
    !> Column names (trailing blanks dropped).
    character(*), intent(in) :: names(:)
    !> Units (trailing blanks dropped).
    character(*), intent(in) :: units(:)
    !> col_* kinds.
    integer, intent(in) :: kinds(:)
    integer :: i
    if (allocated(self%columns)) deallocate (self%columns)
    allocate (self%columns(size(names)))
    do i = 1, size(names)
      self%columns(i) = column(trim(names(i)), trim(units(i)), kinds(i))
    end do
  end subroutine set_columns

  !> Index of the column called `name` (0 when there is none).
  pure integer function column_index(self, name)
    class(step_table_t), intent(in) :: self
    !> Column name.
    character(*), intent(in) :: name
    integer :: i
    column_index = 0
    do i = 1, size(self%columns)
      if (self%columns(i)%name == name) then
        column_index = i
        return
      end if
    end do
  end function column_index

  !> The DYNAMICS records of the run, in print order (the DYNAMICS block, JSON "dynamics",
  !> the summary's dyn_ columns): the cycle's figures, then per pair force its peak with the
  !> true motion, at constant speed and their difference in percent of the latter. None
  !> without a steady cycle.
  pure function dynamics_records(self) result(list)
    class(step_table_t), intent(in) :: self
    type(echo_record_t), allocatable :: list(:)
    integer :: i
    real(wp) :: difference
    allocate (list(0))
    if (.not. self%dynamics%present) return
    associate (d => self%dynamics)
      if (d%drive_table) then
        ! a driving-moment table: its mean, the scale it was given and its extremes
        call add("M_d", d%m_d, "N*m")
        call add("M_d_scale", d%m_d_scale, "")
        call add("M_d_max", d%m_d_max, "N*m")
        call add("M_d_min", d%m_d_min, "N*m")
      else
        call add("M_d", d%m_d, "N*m")
      end if
      call add("J_rotor", d%j_rotor, "kg*m^2")
      call add("J_red_min", d%j_red_min, "kg*m^2")
      call add("J_red_max", d%j_red_max, "kg*m^2")
      call add("J_flywheel", d%j_flywheel, "kg*m^2")
      call add_flywheel_disc()
      if (d%delta > 0.0_wp) then
        call add("J_flywheel_textbook", d%j_flywheel_textbook, "kg*m^2")
        if (d%j_flywheel > 0.0_wp) call add("textbook_difference", &
          100.0_wp * (d%j_flywheel_textbook - d%j_flywheel) / d%j_flywheel, "%")
      end if
      call add("omega_mean", d%omega_mean, "rad/s")
      call add("omega_max", d%omega_max, "rad/s")
      call add("phi_omega_max", d%phi_omega_max, "deg")
      call add("omega_min", d%omega_min, "rad/s")
      call add("phi_omega_min", d%phi_omega_min, "deg")
      if (d%delta_asked > 0.0_wp) call add("delta_asked", d%delta_asked, "")
      call add("delta", d%delta, "")
      call add("period", d%period, "s")
    end associate
    if (.not. allocated(self%run_tally%peaks)) return
    do i = 1, size(self%run_tally%peaks)
      associate (p => self%run_tally%peaks(i))
        call add(p%name//"_peak", p%true_motion, "N")
        call add(p%name//"_peak_constant_speed", p%constant_speed, "N")
        difference = 0.0_wp
        if (p%constant_speed > 0.0_wp) difference = 100.0_wp * (p%true_motion - p%constant_speed) / p%constant_speed
        call add(p%name//"_peak_difference", difference, "%")
      end associate
    end do
  contains
    pure subroutine add(name, value, unit)
      character(*), intent(in) :: name, unit
      real(wp), intent(in) :: value
      list = [list, echo_record_t(kind=echo_real_kind, name=name, unit=unit, values=[value])]
    end subroutine add
    !> The flywheel as a disc (flywheel_disc); without a flywheel the disc's figures are null
    !> (a record of echo_real_kind with an empty `text`: JSON null, the DYNAMICS block "none",
    !> 0 in a summary) and the note says so.
    pure subroutine add_flywheel_disc()
      real(wp) :: diameter, width, mass
      associate (d => self%dynamics)
        call add("flywheel_density", d%flywheel_density, "kg/m^3")
        call add("flywheel_width_ratio", d%flywheel_width_ratio, "")
        if (d%j_flywheel > 0.0_wp) then
          call flywheel_disc(d, diameter, width, mass)
          call add("flywheel_D", diameter, "m")
          call add("flywheel_b", width, "m")
          call add("flywheel_m", mass, "kg")
          list = [list, echo_record_t(kind=echo_text_kind, name="flywheel_note", unit="", values=[0.0_wp], &
                                      text=flywheel_disc_note)]
        else
          call add_null("flywheel_D", "m")
          call add_null("flywheel_b", "m")
          call add_null("flywheel_m", "kg")
          list = [list, echo_record_t(kind=echo_text_kind, name="flywheel_note", unit="", values=[0.0_wp], &
                                      text=flywheel_none_note)]
        end if
      end associate
    end subroutine add_flywheel_disc
    pure subroutine add_null(name, unit)
      character(*), intent(in) :: name, unit
      list = [list, echo_record_t(kind=echo_real_kind, name=name, unit=unit, values=[0.0_wp], text="")]
    end subroutine add_null
  end function dynamics_records

  !> Moment of inertia turning with the input link besides the mechanism's links: the
  !> flywheel and the rotor of a steady cycle's DYNAMICS block (J_flywheel + J_rotor),
  !> kg*m^2; 0 without them.
  pure real(wp) function shaft_inertia(self)
    class(step_table_t), intent(in) :: self
    shaft_inertia = 0.0_wp
    if (self%dynamics%present) shaft_inertia = self%dynamics%j_flywheel + self%dynamics%j_rotor
  end function shaft_inertia

  !> Allocate `n` rows of zeros for the columns defined so far.
  pure subroutine allocate_rows(self, n, error)
    class(step_table_t), intent(inout) :: self
    !> Number of rows.
    integer, intent(in) :: n
    !> The rows do not fit in memory (exit 2; when given: without it, the allocation's own
    !> failure ends the program).
    type(error_t), allocatable, intent(out), optional :: error
    integer :: stat
    ! the block before's rows when they have the shape (no fresh pages for every block)
    if (allocated(self%rows)) then
      if (size(self%rows, 1) == size(self%columns) .and. size(self%rows, 2) == n) then
        self%rows = 0.0_wp
        return
      end if
      deallocate (self%rows)
    end if
    allocate (self%rows(size(self%columns), n), source=0.0_wp, stat=stat)
    if (stat /= 0 .and. present(error)) call out_of_memory(error, "the rows of a block of "//int_str(n)// &
      " steps of "//int_str(size(self%columns))//" columns", 8_int64 * n * size(self%columns))
  end subroutine allocate_rows

  !> Whether column `c` holds whole numbers (flags and counts), written without a fraction.
  pure logical function is_whole(self, c)
    class(step_table_t), intent(in) :: self
    !> Column index.
    integer, intent(in) :: c
    is_whole = self%columns(c)%kind == col_flag .or. self%columns(c)%kind == col_count
  end function is_whole

  !> Whether row k (of the rows now in the table) is void: one of the void_flags columns
  !> is nonzero there.
  pure logical function is_void(self, k)
    class(step_table_t), intent(in) :: self
    !> Row (1 .. row_count()).
    integer, intent(in) :: k
    is_void = .false.
    if (allocated(self%void_flags)) is_void = any(self%rows(self%void_flags, k) /= 0.0_wp)
  end function is_void

  !> Whether the cell of column c in row k has no value: a voidable column in a void row.
  pure logical function void_cell(self, c, k)
    class(step_table_t), intent(in) :: self
    !> Column index.
    integer, intent(in) :: c
    !> Row (1 .. row_count()).
    integer, intent(in) :: k
    void_cell = .false.
    if (self%columns(c)%voidable) void_cell = self%is_void(k)
  end function void_cell

  !> The self-check figures of the block just solved (the run pipeline merges them into the
  !> run's: kinetostat_run_tally).
  pure subroutine set_selfcheck(self, max_residual, max_mismatch, driver, residual_row, mismatch_row)
    class(step_table_t), intent(inout) :: self
    !> Largest relative equilibrium residual over all links and rows of the block.
    real(wp), intent(in) :: max_residual
    !> Largest relative mismatch of the driving effort.
    real(wp), intent(in) :: max_mismatch
    !> Name of the driving quantity ("M1", "F2", ...).
    character(*), intent(in) :: driver
    !> Row of this block (1..) with the largest residual, and with the largest mismatch.
    integer, intent(in), optional :: residual_row, mismatch_row
    integer :: row
    row = 0
    if (present(residual_row)) row = self%row_offset + residual_row
    self%block_tally%residual = running_max_t(max_residual, row, .true.)
    row = 0
    if (present(mismatch_row)) row = self%row_offset + mismatch_row
    self%block_tally%mismatch = running_max_t(max_mismatch, row, .true.)
    self%driver = driver
  end subroutine set_selfcheck

  !> set_selfcheck from the figures of every row of the block: the largest of each and its
  !> row (worst_row: the first NaN, else the largest).
  pure subroutine set_selfcheck_rows(self, residuals, mismatches, driver)
    class(step_table_t), intent(inout) :: self
    !> Relative equilibrium residual of every row of the block.
    real(wp), intent(in) :: residuals(:)
    !> Relative mismatch of the driving effort of every row of the block.
    real(wp), intent(in) :: mismatches(:)
    !> Name of the driving quantity ("M1", "F2", ...).
    character(*), intent(in) :: driver
    call self%set_selfcheck(maxval(residuals), maxval(mismatches), driver, worst_row(residuals), worst_row(mismatches))
  end subroutine set_selfcheck_rows

  !> Index of the worst self-check figure of a block: the first NaN, else the largest (1
  !> for an empty array).
  pure integer function worst_row(figures)
    !> Self-check figures of the block's rows.
    real(wp), intent(in) :: figures(:)
    integer :: k
    worst_row = 1
    if (size(figures) == 0) return
    do k = 1, size(figures)
      if (ieee_is_nan(figures(k))) then
        worst_row = k
        return
      end if
    end do
    worst_row = maxloc(figures, 1)
  end function worst_row

  !> Number of rows.
  pure integer function row_count(self)
    class(step_table_t), intent(in) :: self
    row_count = 0
    if (allocated(self%rows)) row_count = size(self%rows, 2)
  end function row_count

  !> Note an allocation of the table that failed: what did not fit and its size (the first
  !> one is kept; kinetostat_run stops the run with it).
  pure subroutine lack_room(self, what, bytes)
    class(step_table_t), intent(inout) :: self
    character(*), intent(in) :: what
    integer(int64), intent(in) :: bytes
    if (.not. allocated(self%no_room)) self%no_room = what//" ("//int64_str(bytes)//" bytes)"
  end subroutine lack_room

  !> The run's row number of row k of the rows held (the step of a drawing, of a deck's
  !> per-step values).
  pure integer function run_row(self, k)
    class(step_table_t), intent(in) :: self
    !> Row, 1 .. row_count().
    integer, intent(in) :: k
    if (allocated(self%row_numbers)) then
      run_row = self%row_numbers(k)
    else
      run_row = self%row_offset + k
    end if
  end function run_row

  !> The number of rows of the whole run (of the rows held when nothing says more).
  pure integer function run_rows(self)
    class(step_table_t), intent(in) :: self
    run_rows = max(self%total_rows, self%row_offset + self%row_count())
  end function run_rows

  !> Append a warning.
  pure subroutine add_warning(self, text)
    class(step_table_t), intent(inout) :: self
    !> The warning (one line, without the "kinetostat: warning: <deck>: " prefix).
    character(*), intent(in) :: text
    if (.not. allocated(self%warnings)) allocate (self%warnings(0))
    self%warnings = [self%warnings, remark_t(text)]
  end subroutine add_warning

  !> Note a load applied per row: when it switches between two values (on and off: a
  !> working and an idle value), the rows where it changes are marked in `load_changes`
  !> (for the coarse-step warning of kinetostat_summary). A load with more than two values
  !> (a curve, such as a gas force) is not a switch and marks nothing.
  pure subroutine note_load(self, values)
    class(step_table_t), intent(inout) :: self
    !> The load's value at every row (any unit).
    real(wp), intent(in) :: values(:)
    integer :: n, other, stat
    n = size(values)
    if (.not. allocated(self%load_changes)) then
      allocate (self%load_changes(n), source=.false., stat=stat)
      if (stat /= 0) then
        call self%lack_room("the load switches of "//int_str(n)//" steps", 4_int64 * n)
        return
      end if
    end if
    if (n < 2 .or. size(self%load_changes) /= n) return
    other = findloc(values /= values(1), .true., dim=1)
    if (other == 0) return
    if (any(values /= values(1) .and. values /= values(other))) return
    self%load_changes(2:) = self%load_changes(2:) .or. values(2:) /= values(:n - 1)
    self%load_changes(1) = self%load_changes(1) .or. values(1) /= values(n)
  end subroutine note_load

  !> Number of warnings of the run.
  pure integer function warning_count(self)
    class(step_table_t), intent(in) :: self
    warning_count = 0
    if (allocated(self%warnings)) warning_count = size(self%warnings)
  end function warning_count

  pure subroutine push_echo(self, record)
    class(step_table_t), intent(inout) :: self
    type(echo_record_t), intent(in) :: record
    type(echo_record_t), allocatable :: grown(:)
    integer :: i
    if (.not. allocated(self%echo)) allocate (self%echo(16))
    if (self%echo_count == size(self%echo)) then
      allocate (grown(2 * size(self%echo)))
      ! moved, not copied: an echoed array is held once
      do i = 1, self%echo_count
        call move_record(self%echo(i), grown(i))
      end do
      call move_alloc(grown, self%echo)
    end if
    self%echo_count = self%echo_count + 1
    self%echo(self%echo_count) = record
  end subroutine push_echo

  !> The next chunk of an echoed array of `n` values: values first .. last, a multiple of
  !> `whole` values long (a writer's values per line) unless it is the last; the cursor is
  !> left at `last` when values remain, at 0 when the array is done.
  pure subroutine take(self, n, whole, first, last)
    class(echo_cursor_t), intent(inout) :: self
    !> Values of the array.
    integer, intent(in) :: n
    !> The chunk is a multiple of this many values.
    integer, intent(in) :: whole
    !> First and last value of the chunk.
    integer, intent(out) :: first, last
    integer :: chunk
    chunk = self%chunk
    if (chunk <= 0) chunk = echo_chunk_values
    chunk = max(1, chunk / whole) * whole
    first = self%value + 1
    last = min(n, self%value + chunk)
    self%value = 0
    if (last < n) self%value = last
  end subroutine take

  !> Move a record's contents to `to` (its arrays change owner, nothing is copied).
  pure subroutine move_record(from, to)
    type(echo_record_t), intent(inout) :: from
    type(echo_record_t), intent(inout) :: to
    to%kind = from%kind
    to%int_value = from%int_value
    to%logical_value = from%logical_value
    to%overridden = from%overridden
    if (allocated(from%name)) call move_alloc(from%name, to%name)
    if (allocated(from%unit)) call move_alloc(from%unit, to%unit)
    if (allocated(from%values)) call move_alloc(from%values, to%values)
    if (allocated(from%run_end)) call move_alloc(from%run_end, to%run_end)
    if (allocated(from%text)) call move_alloc(from%text, to%text)
  end subroutine move_record

  !> Whether two reals have the same bits (0 and -0 differ; a NaN equals its own bits).
  elemental logical function same_bits(a, b)
    real(wp), intent(in) :: a, b
    same_bits = transfer(a, 0_int64) == transfer(b, 0_int64)
  end function same_bits

  !> Number of values of the record (of an array: its length, however it is kept).
  pure integer function value_count(self)
    class(echo_record_t), intent(in) :: self
    value_count = 0
    if (allocated(self%run_end)) then
      if (size(self%run_end) > 0) value_count = self%run_end(size(self%run_end))
    else if (allocated(self%values)) then
      value_count = size(self%values)
    end if
  end function value_count

  !> Values first .. last of the record, in order, into `buf(1:last - first + 1)`.
  pure subroutine get_values(self, first, last, buf)
    class(echo_record_t), intent(in) :: self
    !> First value wanted (1-based).
    integer, intent(in) :: first
    !> Last value wanted (<= value_count()).
    integer, intent(in) :: last
    !> The values.
    real(wp), intent(out) :: buf(:)
    integer :: lo, hi, mid, i, r
    if (.not. allocated(self%run_end)) then
      buf(1:last - first + 1) = self%values(first:last)
      return
    end if
    ! the run holding `first`: the lowest r with run_end(r) >= first
    lo = 1
    hi = size(self%run_end)
    do while (lo < hi)
      mid = (lo + hi) / 2
      if (self%run_end(mid) >= first) then
        hi = mid
      else
        lo = mid + 1
      end if
    end do
    r = lo
    do i = first, last
      if (i > self%run_end(r)) r = r + 1
      buf(i - first + 1) = self%values(r)
    end do
  end subroutine get_values

  !> Echo a deck value: a real, an integer or a logical (echo_real, echo_int, echo_logical).
  pure subroutine echo_value(self, name, value, unit)
    class(step_table_t), intent(inout) :: self
    !> Name as printed.
    character(*), intent(in) :: name
    !> Value: real(wp), integer or logical.
    class(*), intent(in) :: value
    !> Unit text (or a remark).
    character(*), intent(in) :: unit
    select type (value)
    type is (real(wp))
      call push_echo(self, echo_record_t(kind=echo_real_kind, name=name, unit=unit, values=[value]))
    type is (integer)
      call push_echo(self, echo_record_t(kind=echo_int_kind, name=name, unit=unit, int_value=value))
    type is (logical)
      call push_echo(self, echo_record_t(kind=echo_logical_kind, name=name, unit=unit, logical_value=value))
    end select
  end subroutine echo_value

  !> Echo an array of reals.
  pure subroutine echo_array(self, name, values, unit)
    class(step_table_t), intent(inout) :: self
    !> Name as printed.
    character(*), intent(in) :: name
    !> Values.
    real(wp), intent(in) :: values(:)
    !> Unit text.
    character(*), intent(in) :: unit
    integer :: runs, i, r, stat
    call push_echo(self, echo_record_t(kind=echo_array_kind, name=name, unit=unit))
    associate (e => self%echo(self%echo_count))
      ! runs of equal bits (so -0 and 0, and NaNs, stay apart and come back as they were)
      runs = min(size(values), 1)
      do i = 2, size(values)
        if (.not. same_bits(values(i), values(i - 1))) runs = runs + 1
      end do
      ! a run costs a value and an index: keep runs only when they save memory
      if (3 * runs > 2 * size(values)) then
        allocate (e%values(size(values)), stat=stat)
        if (stat /= 0) then
          call self%lack_room("the echo of "//name//" ("//int_str(size(values))//" values)", 8_int64 * size(values))
          return
        end if
        e%values = values
      else
        allocate (e%values(runs), stat=stat)
        if (stat == 0) allocate (e%run_end(runs), stat=stat)
        if (stat /= 0) then
          call self%lack_room("the echo of "//name//" ("//int_str(runs)//" runs of values)", 12_int64 * runs)
          return
        end if
        r = min(size(values), 1)
        if (r == 1) then
          e%values(1) = values(1)
          e%run_end(1) = 1
        end if
        do i = 2, size(values)
          if (.not. same_bits(values(i), values(i - 1))) then
            r = r + 1
            e%values(r) = values(i)
          end if
          e%run_end(r) = i
        end do
      end if
    end associate
  end subroutine echo_array

  !> Echo a text value.
  pure subroutine echo_text(self, name, text)
    class(step_table_t), intent(inout) :: self
    !> Name as printed.
    character(*), intent(in) :: name
    !> Value.
    character(*), intent(in) :: text
    call push_echo(self, echo_record_t(kind=echo_text_kind, name=name, unit="", text=text))
  end subroutine echo_text

  !> A sub-heading inside the INPUT DATA block.
  pure subroutine echo_heading(self, text)
    class(step_table_t), intent(inout) :: self
    !> Heading text.
    character(*), intent(in) :: text
    call push_echo(self, echo_record_t(kind=echo_heading_kind, name=text, unit=""))
  end subroutine echo_heading

  !> A pre-formatted line inside the INPUT DATA block.
  pure subroutine echo_line(self, text)
    class(step_table_t), intent(inout) :: self
    !> The line.
    character(*), intent(in) :: text
    call push_echo(self, echo_record_t(kind=echo_line_kind, name=text, unit=""))
  end subroutine echo_line

  !> A real value of the summary block (a result of the whole run).
  pure subroutine summary_real(self, name, value, unit)
    class(step_table_t), intent(inout) :: self
    !> Name as printed.
    character(*), intent(in) :: name
    !> Value.
    real(wp), intent(in) :: value
    !> Unit text.
    character(*), intent(in) :: unit
    call append_record(self%summary, echo_record_t(kind=echo_real_kind, name=name, unit=unit, values=[value]))
  end subroutine summary_real

  !> A line of text of the summary block (translated by the table writer's glossary).
  pure subroutine summary_line(self, text)
    class(step_table_t), intent(inout) :: self
    !> The line (an English glossary key).
    character(*), intent(in) :: text
    call append_record(self%summary, echo_record_t(kind=echo_line_kind, name=text, unit=""))
  end subroutine summary_line

  !> `record` appended to `list` (allocated when it is not).
  pure subroutine append_record(list, record)
    !> The records.
    type(echo_record_t), allocatable, intent(inout) :: list(:)
    !> The record to append.
    type(echo_record_t), intent(in) :: record
    if (.not. allocated(list)) allocate (list(0))
    list = [list, record]
  end subroutine append_record

end module kinetostat_step_table
