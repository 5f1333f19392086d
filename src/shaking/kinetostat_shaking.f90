!> The shaking force and moment of a linkage and the total force and moment it exerts on the
!> frame, per step, from the step table's kinematics columns and the mechanism's mass model
!> (one stage for every linkage: the mechanisms only list their links and frame pairs).
!>
!> Shaking force F_shake = -sum m_i a_Si, the resultant of the inertia forces; shaking moment
!> about the origin of the mechanism's frame M_shake = -sum (r_Si x m_i a_Si) - sum J_Si eps_i,
!> and with a steady cycle (machine dynamics) the couple -(J_fw + j_rotor) eps1 of the flywheel
!> and the rotor turning with the input link (their centres on its axis: no force).
!> The frame's total (force and moment the mechanism exerts on the frame): minus every frame
!> pair's reaction (force at its point, and a prismatic pair's reaction moment) minus the
!> driving moment (its reaction on the motor's housing). By d'Alembert it equals the shaking
!> force and moment plus the weights and the external loads.
module kinetostat_shaking
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t, fatal_error, exit_usage
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_step_table, only: step_table_t, col_component, col_force, col_force_angle, col_moment
  implicit none
  private
  public :: add_shaking, shaking_column_names

  !> The columns add_shaking appends, in order (M_frame only where the frame's moment is known;
  !> the F_frame columns only where the mechanism lists its frame pairs).
  character(*), parameter :: shaking_column_names(*) = [character(len=9) :: "F_shake", "F_shakeG", "F_shake_x", &
    "F_shake_y", "M_shake", "F_frame_x", "F_frame_y", "M_frame"]

contains

  !> Append (with a run's first block) and fill for the rows of the block the columns
  !> F_shake (N, magnitude), F_shakeG (deg, its angle in [0, 360), as a pair force's; so the
  !> SVG sheet draws its hodograph), F_shake_x, F_shake_y (N), M_shake (N*m, about the origin),
  !> F_frame_x, F_frame_y (N) and M_frame (N*m, about the origin) of the force and moment on
  !> the frame. The table must hold the kinematics columns the model names.
  pure subroutine add_shaking(table, model, error)
    !> The results with their kinematics columns (one block of the run).
    type(step_table_t), intent(inout) :: table
    !> The mechanism's moving links, gravity and frame pairs.
    type(mass_model_t), intent(in) :: model
    !> A column the model names that the table lacks (a mechanism without kinematics).
    type(error_t), allocatable, intent(out) :: error
    integer, allocatable :: sx(:), sy(:), ax(:), ay(:), eps(:), fx(:), fy(:), px(:), py(:), pm(:)
    real(wp), allocatable :: turn(:)
    integer :: nb, np, i, k, c0, drive, eps_in
    logical :: frame, frame_moment
    real(wp) :: f(2), m, g(2), mf, r(2), a(2), j_input

    nb = size(model%bodies)
    allocate (sx(nb), sy(nb), ax(nb), ay(nb), eps(nb))
    do i = 1, nb
      associate (b => model%bodies(i))
        call need("x_"//b%centre, sx(i), error)
        call need("y_"//b%centre, sy(i), error)
        call need("ax_"//b%centre, ax(i), error)
        call need("ay_"//b%centre, ay(i), error)
        if (allocated(error)) return
        eps(i) = table%column_index("eps"//b%link)
      end associate
    end do
    frame = .false.
    frame_moment = .false.
    np = 0
    if (allocated(model%frame_pairs)) np = size(model%frame_pairs)
    allocate (fx(np), fy(np), px(np), py(np), pm(np), turn(np))
    px = 0
    py = 0
    pm = 0
    if (np > 0) then
      frame = .true.
      frame_moment = .true.
      do i = 1, np
        associate (p => model%frame_pairs(i))
          call need(p%force//"_x", fx(i), error)
          call need(p%force//"_y", fy(i), error)
          if (allocated(error)) return
          turn(i) = table%columns(fx(i))%frame_angle * deg_to_rad
          if (len(p%point) == 0) then
            frame_moment = .false.
          else
            call need("x_"//p%point, px(i), error)
            call need("y_"//p%point, py(i), error)
          end if
          if (len(p%moment) > 0) call need(p%moment, pm(i), error)
          if (allocated(error)) return
        end associate
      end do
    end if
    drive = 0
    if (allocated(model%drive)) then
      if (len(model%drive) > 0) then
        call need(model%drive, drive, error)
        if (allocated(error)) return
      end if
    end if

    ! a steady cycle: the flywheel and the rotor on the input shaft, with the input's eps1
    j_input = 0.0_wp
    eps_in = 0
    if (table%dynamics%present) then
      j_input = table%shaft_inertia()
      eps_in = table%column_index("eps1")
    end if

    c0 = table%column_index(shaking_column_names(1))
    if (c0 == 0) then
      c0 = size(table%columns) + 1
      call table%add_column("F_shake", "N", col_force)
      call table%add_column("F_shakeG", "deg", col_force_angle)
      call table%add_column("F_shake_x", "N", col_component)
      call table%add_column("F_shake_y", "N", col_component)
      call table%add_column("M_shake", "N*m", col_moment)
      if (frame) then
        call table%add_column("F_frame_x", "N", col_component)
        call table%add_column("F_frame_y", "N", col_component)
        if (frame_moment) call table%add_column("M_frame", "N*m", col_moment)
      end if
      call grow_rows(table)
    end if

    do k = 1, table%row_count()
      f = 0.0_wp
      m = 0.0_wp
      do i = 1, nb
        associate (b => model%bodies(i))
          a = [table%rows(ax(i), k), table%rows(ay(i), k)]
          r = [table%rows(sx(i), k), table%rows(sy(i), k)]
          f = f - b%mass * a
          m = m - b%mass * cross(r, a)
          if (eps(i) > 0) m = m - b%inertia * table%rows(eps(i), k)
        end associate
      end do
      if (eps_in > 0) m = m - j_input * table%rows(eps_in, k)
      table%rows(c0, k) = hypot(f(1), f(2))
      table%rows(c0 + 1, k) = 0.0_wp
      if (table%rows(c0, k) > 0.0_wp) table%rows(c0 + 1, k) = modulo(atan2(f(2), f(1)) * rad_to_deg, 360.0_wp)
      table%rows(c0 + 2, k) = f(1)
      table%rows(c0 + 3, k) = f(2)
      table%rows(c0 + 4, k) = m
      if (.not. frame) cycle
      g = 0.0_wp
      mf = 0.0_wp
      do i = 1, np
        a = [table%rows(fx(i), k), table%rows(fy(i), k)]
        ! the components' frame turned into the position frame
        a = [cos(turn(i)) * a(1) - sin(turn(i)) * a(2), sin(turn(i)) * a(1) + cos(turn(i)) * a(2)]
        g = g - a
        if (px(i) > 0) mf = mf - cross([table%rows(px(i), k), table%rows(py(i), k)], a)
        if (pm(i) > 0) mf = mf - table%rows(pm(i), k)
      end do
      if (drive > 0) mf = mf - table%rows(drive, k)
      table%rows(c0 + 5, k) = g(1)
      table%rows(c0 + 6, k) = g(2)
      if (frame_moment) table%rows(c0 + 7, k) = mf
    end do

  contains

    !> Index of column `name` into `c`; an error when the table lacks it.
    pure subroutine need(name, c, error)
      character(*), intent(in) :: name
      integer, intent(out) :: c
      type(error_t), allocatable, intent(inout) :: error
      c = table%column_index(name)
      if (c == 0 .and. .not. allocated(error)) then
        call fatal_error(error, exit_usage, table%deck//": &"//table%mechanism//": --shaking: the results have "// &
          "no column "//name//" (only linkage mechanisms report the shaking force)")
      end if
    end subroutine need
  end subroutine add_shaking

  !> z component of the cross product of two plane vectors.
  pure real(wp) function cross(p, q)
    real(wp), intent(in) :: p(2), q(2)
    cross = p(1) * q(2) - p(2) * q(1)
  end function cross

  !> Give `rows` the columns added since it was allocated (zero in every row).
  pure subroutine grow_rows(table)
    type(step_table_t), intent(inout) :: table
    real(wp), allocatable :: grown(:, :)
    integer :: done
    done = size(table%rows, 1)
    if (done >= size(table%columns)) return
    allocate (grown(size(table%columns), size(table%rows, 2)), source=0.0_wp)
    grown(1:done, :) = table%rows
    call move_alloc(grown, table%rows)
  end subroutine grow_rows

end module kinetostat_shaking
