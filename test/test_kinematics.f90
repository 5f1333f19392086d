!> Kinematics columns (--kinematics) of every mechanism, tested through the step table the
!> writers read: link speeds and accelerations and the accelerations of the centres of mass
!> against central finite differences of the reported angles and positions over the input
!> angle (every mechanism, both the omega^2 and the eps part where the input's speed is
!> prescribed); force components against magnitude and angle (every bundled deck); the
!> generic twins' positions, angles, accelerations and components against the dedicated
!> programs' (T.FTN and PR 3207); kinematics columns absent from the default CSV and JSON.
module test_kinematics
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name
  use kinetostat_step_table, only: step_table_t, col_force
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_csv_writer, only: write_csv
  use kinetostat_json_writer, only: write_json
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_registry, only: create_mechanism
  use kinetostat_pr3207_layout, only: pr3207_mechanism_t
  use kinetostat_pr3050_layout, only: pr3050_mechanism_t
  use kinetostat_sixbar_layout, only: sixbar_mechanism_t
  use kinetostat_assur_layout, only: assur_mechanism_t
  use kinetostat_assur_deck, only: assur_omega1, load_schedule_t, load_constant
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_kinematics_tests

  !> Half step of the finite differences, deg (1.7e-3 rad): truncation error ~ h^2/12
  !> relative (2.5e-7), roundoff of the second difference ~ 1e-16/h^2 (4e-11) relative.
  real(wp), parameter :: h_deg = 0.1_wp
  !> Tolerance of a finite-difference check, relative to the largest value of the column over
  !> the sweep (a bound of both the truncation and the roundoff above, with margin).
  real(wp), parameter :: fd_tol = 2.0e-5_wp
  !> Roundoff of the differences: a reported value carries ~1 ulp of its magnitude |q| (and its
  !> input angle as much), so a first difference errs by up to ~fd_roundoff*|q|/h and a
  !> second by ~fd_roundoff*|q|/h^2; added to the tolerance (it dominates where the exact
  !> value is 0, e.g. eps1 = 0 of a crank turning at constant speed).
  real(wp), parameter :: fd_roundoff = 16.0_wp * epsilon(1.0_wp)
  !> Tolerance of the twin comparisons and of components vs magnitude and angle, relative
  !> to the largest value of the column (resp. of the step's forces).
  real(wp), parameter :: same_tol = 1.0e-9_wp
  !> Bundled decks (all mechanisms; data/assur_toggle.nml stops at its dead position).
  character(len=32), parameter :: bundled(*) = [character(len=32) :: "data/pr3207.nml", "data/pr3050.nml", &
    "data/assur_pr3050.nml", &
    "data/sixbar.nml", "data/sixbar_example.nml", "data/assur_pr3207.nml", "data/assur_sixbar.nml", &
    "data/assur_slider_crank.nml", "data/gears_reducer.nml", "data/gears_bevel.nml", &
    "data/gears_planetary.nml", "data/cam_translating.nml", "data/cam_flat.nml"]

contains

  subroutine run_kinematics_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_fd_pr3207(t)
    call test_fd_pr3050(t)
    call test_fd_sixbar(t)
    call test_fd_assur(t)
    call test_components(t)
    call test_link_axes(t)
    call test_twin_sixbar(t)
    call test_twin_pr3207(t)
    call test_twin_pr3050(t)
    call test_default_hides(t)
    call test_sketch(t)
  end subroutine run_kinematics_tests

  !> One table whose rows are the rows of three runs in turn (run 1 row k, run 2 row k, run 3
  !> row k, ...): the triples check_fd reads when the runs' input angles are shifted by
  !> -h, 0, +h (decks whose input angle is implied by a start and a step).
  function interleaved(tables) result(table)
    type(step_table_t), intent(in) :: tables(3)
    type(step_table_t) :: table
    integer :: j
    table = tables(2)
    if (allocated(table%rows)) deallocate (table%rows)
    if (any([(tables(j)%row_count() /= tables(2)%row_count(), j=1, 3)])) return
    allocate (table%rows(size(tables(2)%rows, 1), 3 * tables(2)%row_count()))
    do j = 1, 3
      table%rows(:, j::3) = tables(j)%rows
    end do
  end function interleaved

  !> Load a deck file into memory; a failure is a failed check.
  subroutine load(t, path, source, ok)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: path
    type(deck_source_t), intent(out) :: source
    logical, intent(out) :: ok
    type(error_t), allocatable :: error
    call load_deck(path, source, error)
    ok = .not. allocated(error)
    if (.not. ok) call check_true(t, path//" loads", .false., error%message)
  end subroutine load

  !> Solve a mechanism whose deck is read into a step table, as the run pipeline does.
  subroutine solve_into(t, label, mech, path, table)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: label
    class(mechanism_t), intent(in) :: mech
    character(*), intent(in) :: path
    type(step_table_t), intent(out) :: table
    type(error_t), allocatable :: error
    table%deck = path
    table%row_name = "step"
    call mech%solve(table, error)
    if (allocated(error)) call check_true(t, label//" solves", .false., error%message)
  end subroutine solve_into

  !> Read and solve a bundled deck through the registry.
  subroutine run_deck(t, path, table, ok)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: path
    type(step_table_t), intent(out) :: table
    logical, intent(out) :: ok
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    class(mechanism_t), allocatable :: mech
    character(len=:), allocatable :: group
    call load(t, path, source, ok)
    if (.not. ok) return
    call read_group_name(source, group, error)
    ok = .not. allocated(error)
    if (.not. ok) then
      call check_true(t, path//" names its group", .false., error%message)
      return
    end if
    call create_mechanism(trim(group), mech)
    ok = allocated(mech)
    if (.not. ok) then
      call check_true(t, path//" has a mechanism", .false., "group '"//trim(group)//"' unknown")
      return
    end if
    call mech%read_deck(source, error)
    ok = .not. allocated(error)
    if (.not. ok) then
      call check_true(t, path//" reads", .false., error%message)
      return
    end if
    table%mechanism = trim(group)
    call solve_into(t, path, mech, path, table)
    ok = table%row_count() > 0
  end subroutine run_deck

  !> Column `name` of the table, or a failed check.
  function column(t, label, table, name) result(c)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: label
    type(step_table_t), intent(in) :: table
    character(*), intent(in) :: name
    integer :: c
    c = table%column_index(name)
    if (c == 0) call check_true(t, label//": column "//name, .false., "missing")
  end function column

  !> Difference of two angles, deg, wrapped into [-180, 180).
  elemental real(wp) function wrap(d)
    real(wp), intent(in) :: d
    wrap = modulo(d + 180.0_wp, 360.0_wp) - 180.0_wp
  end function wrap

  !> Check every link's omega<i>, eps<i> and every centre's ax_<P>, ay_<P> of a table whose
  !> rows are triples (b - h, b, b + h) of the input angle `input` (column name): with the
  !> input's speed w and acceleration e (per row), omega = q' w and eps = q'' w^2 + q' e,
  !> a = p'' w^2 + p' e with ' = d/d(input) by central differences of phi<i> and x_<P>.
  subroutine check_fd(t, label, table, input, w, e)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: label
    type(step_table_t), intent(in) :: table
    character(*), intent(in) :: input
    real(wp), intent(in) :: w(:), e(:)
    integer :: c, ci, cq, j, k, checked
    real(wp) :: h, d1, d2, scale
    character(len=:), allocatable :: name, of
    logical :: angle
    real(wp) :: roundoff
    if (table%row_count() == 0) return
    ci = column(t, label, table, input)
    if (ci == 0) return
    checked = 0
    do c = 1, size(table%columns)
      name = table%columns(c)%name
      angle = index(name, "omega") == 1 .or. index(name, "eps") == 1
      if (index(name, "omega") == 1) then
        of = "phi"//name(6:)
      else if (index(name, "eps") == 1) then
        of = "phi"//name(4:)
      else if (index(name, "ax_") == 1) then
        of = "x_"//name(4:)
      else if (index(name, "ay_") == 1) then
        of = "y_"//name(4:)
      else
        cycle
      end if
      cq = column(t, label, table, of)
      if (cq == 0) cycle
      scale = max(maxval(abs(table%rows(c, :))), tiny(1.0_wp))
      do j = 1, table%row_count() / 3
        k = 3 * j - 1
        h = (table%rows(ci, k + 1) - table%rows(ci, k - 1)) / 2.0_wp * deg_to_rad
        associate (q => table%rows(cq, k - 1:k + 1))
          if (angle) then
            d1 = wrap(q(3) - q(1)) * deg_to_rad / (2.0_wp * h)
            d2 = (wrap(q(3) - q(2)) - wrap(q(2) - q(1))) * deg_to_rad / h**2
            roundoff = fd_roundoff * maxval(abs(q)) * deg_to_rad
          else
            d1 = (q(3) - q(1)) / (2.0_wp * h)
            d2 = (q(3) - 2.0_wp * q(2) + q(1)) / h**2
            roundoff = fd_roundoff * maxval(abs(q))
          end if
        end associate
        if (index(name, "omega") == 1) then
          call check_close(t, label//": "//name//" = d"//of//"/dt at "//input//" = "// &
                           num(table%rows(ci, k)), d1 * w(k), table%rows(c, k), 0.0_wp, &
                           fd_tol * scale + roundoff * abs(w(k)) / h)
        else
          call check_close(t, label//": "//name//" = d2"//of//"/dt2 at "//input//" = "// &
                           num(table%rows(ci, k)), d2 * w(k)**2 + d1 * e(k), table%rows(c, k), 0.0_wp, &
                           fd_tol * scale + roundoff * (w(k)**2 / h**2 + abs(e(k)) / h))
        end if
      end do
      checked = checked + 1
    end do
    call check_true(t, label//": some kinematics columns checked", checked > 0, "none found")
  end subroutine check_fd

  !> A number for test names.
  pure function num(x) result(s)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(f0.3)') x
    s = trim(buf)
  end function num

  !> `x` in scientific notation (3 significant digits).
  pure function sci(x) result(s)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=24) :: buf
    write (buf, '(es10.2)') x
    s = trim(adjustl(buf))
  end function sci

  !> PR 3207: the deck's crank angles (constant omega1): three runs with phi_start shifted
  !> by -h, 0, +h, their rows interleaved (cutting force off).
  subroutine test_fd_pr3207(t)
    type(test_counts_t), intent(inout) :: t
    type(pr3207_mechanism_t) :: mech, shifted
    type(deck_source_t) :: source
    type(step_table_t) :: tables(3), table
    type(error_t), allocatable :: error
    logical :: ok
    integer :: j
    call load(t, "data/pr3207.nml", source, ok)
    if (.not. ok) return
    call mech%read_deck(source, error)
    if (allocated(error)) return
    do j = 1, 3
      shifted = mech
      shifted%deck%phi_start = mech%deck%phi_start + real(j - 2, wp) * h_deg
      shifted%deck%two_value = .false.
      shifted%deck%f5c_values = spread(0.0_wp, 1, mech%deck%n)
      call solve_into(t, "pr3207 fd", shifted, "data/pr3207.nml", tables(j))
    end do
    table = interleaved(tables)
    call check_fd(t, "pr3207", table, "phi1", spread(mech%deck%p%omega1, 1, 3 * mech%deck%n), &
                  spread(0.0_wp, 1, 3 * mech%deck%n))
  end subroutine test_fd_pr3207

  !> PR 3050: the deck's rocker angles, once with a constant speed and no acceleration, once
  !> at rest with an angular acceleration (the two parts of every eps and a). The angles are
  !> implied by phi3_start and dphi3: three runs with phi3_start shifted by -h, 0, +h.
  subroutine test_fd_pr3050(t)
    type(test_counts_t), intent(inout) :: t
    type(pr3050_mechanism_t) :: mech, shifted
    type(deck_source_t) :: source
    type(step_table_t) :: tables(3), table
    type(error_t), allocatable :: error
    real(wp), allocatable :: w(:), e(:)
    logical :: ok
    integer :: run, j
    call load(t, "data/pr3050.nml", source, ok)
    if (.not. ok) return
    call mech%read_deck(source, error)
    if (allocated(error)) return
    do run = 1, 2
      if (run == 1) then
        w = spread(0.5_wp, 1, 3 * mech%deck%n)
        e = spread(0.0_wp, 1, 3 * mech%deck%n)
      else
        w = spread(0.0_wp, 1, 3 * mech%deck%n)
        e = spread(0.3_wp, 1, 3 * mech%deck%n)
      end if
      do j = 1, 3
        shifted = mech
        shifted%deck%phi_start = mech%deck%phi_start + real(j - 2, wp) * h_deg
        shifted%deck%omega3 = w(1:mech%deck%n)
        shifted%deck%eps3 = e(1:mech%deck%n)
        call solve_into(t, "pr3050 fd", shifted, "data/pr3050.nml", tables(j))
      end do
      table = interleaved(tables)
      call check_fd(t, "pr3050 run "//achar(iachar("0") + run), table, "phi3", w, e)
    end do
  end subroutine test_fd_pr3050

  !> T.FTN: the deck's crank angles from the extreme position (constant omega1): three runs
  !> with phi_start shifted by -h, 0, +h, their rows interleaved (slider load off).
  subroutine test_fd_sixbar(t)
    type(test_counts_t), intent(inout) :: t
    type(sixbar_mechanism_t) :: mech, shifted
    type(deck_source_t) :: source
    type(step_table_t) :: tables(3), table
    type(error_t), allocatable :: error
    logical :: ok
    integer :: j
    call load(t, "data/sixbar.nml", source, ok)
    if (.not. ok) return
    call mech%read_deck(source, error)
    if (allocated(error)) return
    do j = 1, 3
      shifted = mech
      shifted%deck%phi_start = mech%deck%phi_start + real(j - 2, wp) * h_deg
      shifted%deck%f5 = spread(0.0_wp, 1, mech%deck%n)
      call solve_into(t, "sixbar fd", shifted, "data/sixbar.nml", tables(j))
    end do
    table = interleaved(tables)
    call check_fd(t, "sixbar", table, "phi1", spread(mech%deck%p%omega1, 1, 3 * mech%deck%n), &
                  spread(0.0_wp, 1, 3 * mech%deck%n))
  end subroutine test_fd_sixbar

  !> Every bundled generic deck at its own input angles, with a constant crank speed and then
  !> with the crank at rest and accelerating (the loads off). Three runs with the input
  !> angles shifted by -h, 0, +h, their rows interleaved.
  subroutine test_fd_assur(t)
    type(test_counts_t), intent(inout) :: t
    character(len=32), parameter :: decks(*) = [character(len=32) :: "data/assur_pr3207.nml", &
      "data/assur_sixbar.nml", "data/assur_slider_crank.nml", "data/assur_pr3050.nml"]
    type(assur_mechanism_t) :: mech, shifted
    type(deck_source_t) :: source
    type(step_table_t) :: tables(3), table
    type(error_t), allocatable :: error
    real(wp), allocatable :: w(:), e(:)
    logical :: ok
    integer :: i, run, j, k, n
    do i = 1, size(decks)
      call load(t, trim(decks(i)), source, ok)
      if (.not. ok) cycle
      call mech%read_deck(source, error)
      if (allocated(error)) then
        call check_true(t, trim(decks(i))//" reads", .false., error%message)
        cycle
      end if
      n = mech%deck%n
      do run = 1, 2
        if (run == 1) then
          w = spread(assur_omega1(mech%deck, 1), 1, 3 * n)
          e = spread(0.0_wp, 1, 3 * n)
        else
          w = spread(0.0_wp, 1, 3 * n)
          e = spread(40.0_wp, 1, 3 * n)
        end if
        do j = 1, 3
          shifted = mech
          if (allocated(shifted%deck%phi_list)) then
            shifted%deck%phi_list = mech%deck%phi_list + real(j - 2, wp) * h_deg
          else
            shifted%deck%phi_start = mech%deck%phi_start + real(j - 2, wp) * h_deg
          end if
          shifted%deck%force_load = [(load_schedule_t(kind=load_constant, value=0.0_wp), k=1, size(mech%deck%force_load))]
          shifted%deck%moment_load = [(load_schedule_t(kind=load_constant, value=0.0_wp), k=1, size(mech%deck%moment_load))]
          shifted%deck%prescribed = .true.
          shifted%deck%omega1_values = w(1:n)
          shifted%deck%eps1_values = e(1:n)
          call solve_into(t, trim(decks(i))//" fd", shifted, trim(decks(i)), tables(j))
        end do
        table = interleaved(tables)
        call check_fd(t, trim(decks(i))//" run "//achar(iachar("0") + run), table, "phi1", w, e)
      end do
    end do
  end subroutine test_fd_assur

  !> Every bundled deck: every <F>_x, <F>_y equals |F| cos, sin of the angle column <F>G
  !> (and the generic engine's own <F>x, <F>y where the deck prints them).
  subroutine test_components(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    integer :: i, c, cm, cg, cy, cx2, k, checked
    real(wp) :: fmax, theta
    character(len=:), allocatable :: name, f
    logical :: ok
    do i = 1, size(bundled)
      call run_deck(t, trim(bundled(i)), table, ok)
      if (.not. ok) cycle
      checked = 0
      do c = 1, size(table%columns)
        name = table%columns(c)%name
        if (len(name) < 3) cycle
        if (name(len(name) - 1:) /= "_x") cycle
        f = name(1:len(name) - 2)
        cy = column(t, trim(bundled(i)), table, f//"_y")
        cm = table%column_index(f)
        cg = table%column_index(f//"G")
        if (cy == 0 .or. cm == 0 .or. cg == 0) cycle
        cx2 = table%column_index(f//"x")
        do k = 1, table%row_count()
          fmax = max(maxval(abs(table%rows(c, :))), maxval(abs(table%rows(cy, :))), tiny(1.0_wp))
          theta = table%rows(cg, k) * deg_to_rad
          call check_close(t, trim(bundled(i))//" row "//num(real(k, wp))//": "//name//" = "//f//" cos "//f//"G", &
                           table%rows(cm, k) * cos(theta), table%rows(c, k), 0.0_wp, same_tol * fmax)
          call check_close(t, trim(bundled(i))//" row "//num(real(k, wp))//": "//f//"_y = "//f//" sin "//f//"G", &
                           table%rows(cm, k) * sin(theta), table%rows(cy, k), 0.0_wp, same_tol * fmax)
          if (cx2 > 0) call check_close(t, trim(bundled(i))//": "//name//" = "//f//"x", &
                                        table%rows(cx2, k), table%rows(c, k), 0.0_wp, 0.0_wp)
        end do
        checked = checked + 1
      end do
      call check_true(t, trim(bundled(i))//": force components present", checked > 0, "no <F>_x with <F>, <F>G")
    end do
  end subroutine test_components

  !> --frame link: every pair force of every bundled generic deck (<F>_along, <F>_across in
  !> the axes of the link it acts on) turned back by that link's angle phi<link> equals its
  !> global components (<F>_x, <F>_y turned by their frame_angle) at every step, to 1e-12 of
  !> the step's largest force; and the link frames are not all the global one (the check can
  !> fail: somewhere the link-axes components differ from the global ones).
  subroutine test_link_axes(t)
    type(test_counts_t), intent(inout) :: t
    !> Generic decks (data/assur_toggle.nml stops at its dead position).
    character(len=32), parameter :: decks(*) = [character(len=32) :: "data/assur_fourbar.nml", &
      "data/assur_fourbar_global.nml", "data/assur_pr3050.nml", "data/assur_pr3050_friction.nml", &
      "data/assur_pr3207.nml", "data/assur_pr3207_friction.nml", "data/assur_sixbar.nml", &
      "data/assur_sixbar_friction.nml", "data/assur_sixbar_global.nml", "data/assur_slider_crank.nml"]
    !> Tolerance, relative to the step's largest force.
    real(wp), parameter :: tol = 1.0e-12_wp
    type(step_table_t) :: table
    integer :: i, c, cx, cp, k, j, pairs, forces
    real(wp) :: fmax, a, b, g(2), l(2), worst, turned
    character(len=:), allocatable :: name, f
    logical :: ok
    turned = 0.0_wp
    do i = 1, size(decks)
      call run_deck(t, trim(decks(i)), table, ok)
      if (.not. ok) cycle
      pairs = 0
      forces = count(table%columns%kind == col_force)
      do c = 1, size(table%columns)
        if (.not. table%columns(c)%link_axes) cycle
        name = table%columns(c)%name
        if (index(name, "_along") /= len(name) - 5) cycle
        f = name(1:len(name) - 6)
        pairs = pairs + 1
        cx = column(t, trim(decks(i)), table, f//"_x")
        cp = column(t, trim(decks(i)), table, "phi"//table%columns(c)%frame_link)
        if (cx == 0 .or. cp == 0) cycle
        worst = 0.0_wp
        do k = 1, table%row_count()
          fmax = tiny(1.0_wp)
          do j = 1, size(table%columns)
            if (table%columns(j)%kind == col_force) fmax = max(fmax, table%rows(j, k))
          end do
          a = table%columns(cx)%frame_angle * deg_to_rad
          b = table%rows(cp, k) * deg_to_rad
          g = table%rows(cx, k) * [cos(a), sin(a)] + table%rows(cx + 1, k) * [-sin(a), cos(a)]
          l = table%rows(c, k) * [cos(b), sin(b)] + table%rows(c + 1, k) * [-sin(b), cos(b)]
          worst = max(worst, norm2(l - g) / fmax)
          turned = max(turned, norm2(table%rows(c:c + 1, k) - g) / fmax)
        end do
        call check_true(t, trim(decks(i))//": "//f//"_along, "//f//"_across turned by phi"// &
                        table%columns(c)%frame_link//" = global "//f//"_x, "//f//"_y", worst <= tol, &
                        "largest difference "//sci(worst)//" of the step's largest force (limit "//sci(tol)//")")
      end do
      call check_true(t, trim(decks(i))//": one pair of link-axes columns per pair force", pairs == forces .and. &
                      pairs > 0, num(real(pairs, wp))//" pairs of columns, "//num(real(forces, wp))//" forces")
    end do
    call check_true(t, "link axes differ from the global frame somewhere", turned > 1.0e-3_wp, &
                    "largest difference "//sci(turned))
  end subroutine test_link_axes

  !> Every kinematics column of the dedicated deck `path_a` against the generic twin `path_b`
  !> (same input angles): names mapped by `from`/`to` (point names of x_/y_ columns, force
  !> names of component columns), `sign` for a pair named the other way round.
  subroutine check_twin(t, path_a, path_b, from, to, sign)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: path_a, path_b
    character(*), intent(in) :: from(:), to(:)
    real(wp), intent(in) :: sign(:)
    type(step_table_t) :: a, b
    integer :: c, cb, k, m
    real(wp) :: s, scale
    character(len=:), allocatable :: name, mapped, stem, prefix, suffix
    logical :: ok, ok_b
    call run_deck(t, path_a, a, ok)
    call run_deck(t, path_b, b, ok_b)
    if (.not. (ok .and. ok_b)) return
    call check_true(t, path_a//" and "//path_b//": same steps", a%row_count() == b%row_count(), "row counts differ")
    if (a%row_count() /= b%row_count()) return
    do c = 1, size(a%columns)
      if (.not. a%columns(c)%kinematic) cycle
      name = a%columns(c)%name
      prefix = ""
      suffix = ""
      stem = name
      if (index(name, "x_") == 1 .or. index(name, "y_") == 1) then
        prefix = name(1:2)
        stem = name(3:)
      else if (index(name, "ax_") == 1 .or. index(name, "ay_") == 1) then
        prefix = name(1:3)
        stem = name(4:)
      else if (index(name, "_x") == len(name) - 1 .or. index(name, "_y") == len(name) - 1) then
        suffix = name(len(name) - 1:)
        stem = name(1:len(name) - 2)
      end if
      s = 1.0_wp
      mapped = name
      do m = 1, size(from)
        if (stem == trim(from(m))) then
          mapped = prefix//trim(to(m))//suffix
          s = sign(m)
        end if
      end do
      cb = column(t, path_b, b, mapped)
      if (cb == 0) cycle
      scale = max(maxval(abs(a%rows(c, :))), 1.0_wp)
      do k = 1, a%row_count()
        call check_close(t, path_a//" "//name//" = "//path_b//" "//mapped//" row "//num(real(k, wp)), &
                         s * b%rows(cb, k), a%rows(c, k), 0.0_wp, same_tol * scale)
      end do
    end do
  end subroutine check_twin

  !> T.FTN vs its generic twin: joints A B C D E H are the pairs 16 21 32 36 43 45.
  subroutine test_twin_sixbar(t)
    type(test_counts_t), intent(inout) :: t
    call check_twin(t, "data/sixbar.nml", "data/assur_sixbar.nml", &
                    [character(len=3) :: "A", "B", "C", "D", "E", "H"], &
                    [character(len=3) :: "J16", "J21", "J32", "J36", "J43", "J45"], spread(1.0_wp, 1, 6))
  end subroutine test_twin_sixbar

  !> PR 3207 vs its generic twin: joints A B C D are the pairs 16 21 36 43; F34 = -F43.
  subroutine test_twin_pr3207(t)
    type(test_counts_t), intent(inout) :: t
    call check_twin(t, "data/pr3207.nml", "data/assur_pr3207.nml", &
                    [character(len=3) :: "A", "B", "C", "D", "F34"], &
                    [character(len=3) :: "J16", "J21", "J36", "J43", "F43"], &
                    [1.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp])
  end subroutine test_twin_pr3207

  !> PR 3050 vs its generic twin (rocker 3 as the input link, cylinder 1 and rod 2 an RPR
  !> dyad driven by the actuator): joints C A B are the pairs 34 14 23, F32 = -F23, the
  !> cylinder's angle columns are phiL1, omegaL1, epsL1.
  subroutine test_twin_pr3050(t)
    type(test_counts_t), intent(inout) :: t
    call check_twin(t, "data/pr3050.nml", "data/assur_pr3050.nml", &
                    [character(len=8) :: "C", "A", "B", "F32", "phi1", "omega1", "eps1"], &
                    [character(len=8) :: "J34", "J14", "J23", "F23", "phiL1", "omegaL1", "epsL1"], &
                    [1.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, 1.0_wp, 1.0_wp, 1.0_wp])
  end subroutine test_twin_pr3050

  !> The default CSV and JSON carry no kinematics column; with kinematics asked they carry
  !> every one of them.
  subroutine test_default_hides(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    type(text_buffer_t) :: plain, kin, plain_json, kin_json
    logical :: ok
    call run_deck(t, "data/sixbar.nml", table, ok)
    if (.not. ok) return
    call write_csv(table, plain)
    call write_json("T", table, plain_json)
    table%kinematics_shown = .true.
    call write_csv(table, kin)
    call write_json("T", table, kin_json)
    call check_true(t, "default csv has no x_B", index(plain%text(), "x_B") == 0, "x_B in the default csv")
    call check_true(t, "kinematics csv has x_B, F43_x", index(kin%text(), ",x_B,") > 0 .and. &
                    index(kin%text(), ",F43_x,") > 0, "missing")
    call check_true(t, "default json has no kinematic column", index(plain_json%text(), '"kinematic"') == 0, &
                    "found")
    call check_true(t, "kinematics json has x_B", index(kin_json%text(), '"name": "x_B"') > 0, "missing")
  end subroutine test_default_hides

  !> Every linkage deck's sketch names only points the table has (x_<P>, y_<P>), has a
  !> pivot and every moving link with an angle column drawn; gears and cams have none.
  subroutine test_sketch(t)
    type(test_counts_t), intent(inout) :: t
    type(deck_source_t) :: source
    type(step_table_t) :: table
    type(sketch_t) :: sk
    type(error_t), allocatable :: error
    class(mechanism_t), allocatable :: mech
    character(len=:), allocatable :: group, deck
    integer :: i, l, j, links_with_angle, c
    logical :: ok
    do i = 1, size(bundled)
      deck = trim(bundled(i))
      call run_deck(t, deck, table, ok)
      if (.not. ok) cycle
      call load(t, deck, source, ok)
      call read_group_name(source, group, error)
      if (allocated(error)) cycle
      call create_mechanism(group, mech)
      call mech%read_deck(source, error)
      if (allocated(error)) cycle
      call mech%sketch(sk)
      if (group == "gears" .or. group == "cam") then
        call check_true(t, deck//": no sketch", .not. sk%available, "a sketch is given")
        cycle
      end if
      call check_true(t, deck//": sketch available", sk%available, "none")
      if (.not. sk%available) cycle
      call check_true(t, deck//": sketch has a pivot", size(sk%pivots) > 0, "no pivot")
      do l = 1, size(sk%links)
        do j = 1, size(sk%links(l)%points)
          c = column(t, deck//" sketch link "//sk%links(l)%name, table, "x_"//trim(sk%links(l)%points(j)))
        end do
      end do
      do j = 1, size(sk%pivots)
        c = column(t, deck//" sketch pivot", table, "x_"//trim(sk%pivots(j)))
      end do
      if (allocated(sk%guides)) then
        do j = 1, size(sk%guides)
          c = column(t, deck//" sketch guide", table, "y_"//trim(sk%guides(j)%point))
        end do
      end if
      links_with_angle = 0
      do c = 1, size(table%columns)
        if (index(table%columns(c)%name, "omega") == 1) links_with_angle = links_with_angle + 1
      end do
      call check_true(t, deck//": every link with an angle is drawn", size(sk%links) >= links_with_angle, &
                      "fewer sketch links than omega columns")
    end do
  end subroutine test_sketch

end module test_kinematics
