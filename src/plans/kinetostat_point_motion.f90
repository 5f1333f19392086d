!> The velocities and accelerations of the named points of a linkage at every step
!> (--kinematics): vx_<P>, vy_<P> (m/s) of every joint, pivot and centre of mass and ax_<P>,
!> ay_<P> (m/s^2) of every joint and pivot (the centres of mass' accelerations are the
!> mechanism's own columns), in the position frame of the x_<P>, y_<P> columns. They come
!> from the velocity and acceleration fields of the links that the plans solve
!> (kinetostat_plans: every link's v = v0 + omega x r, a = a0 + eps x r - omega^2 r with v0,
!> a0 from the pairs), so every mechanism with a sketch gains them in one place.
module kinetostat_point_motion
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, point_pivot, point_com, points_from_sketch
  use kinetostat_plans_base, only: plan_vector_t
  use kinetostat_plans, only: solve_fields, point_images, field_topology_t, field_topology
  implicit none
  private
  public :: add_point_motion

contains

  !> Put the velocity and acceleration columns of every named point into each row of the
  !> table's block; nothing when the mechanism has no sketch.
  pure subroutine add_point_motion(topo, table, error)
    !> The mechanism's topology.
    type(sketch_t), intent(in) :: topo
    !> The block's results with their kinematics columns (positions, omega, eps).
    type(step_table_t), intent(inout) :: table
    !> A named point without position columns.
    type(error_t), allocatable, intent(out) :: error
    type(drawing_t) :: drawing
    type(field_topology_t) :: known
    type(plan_vector_t), allocatable :: v(:), a(:)
    real(wp), allocatable :: omega(:), eps(:), v0(:, :), a0(:, :), none(:, :)
    real(wp) :: residual
    !> Columns found once for the block: each link's omega and eps, each point's x and y.
    integer, allocatable :: c_omega(:), c_eps(:), cx(:), cy(:), image(:)
    integer :: k, i, nl, ip, iv
    if (.not. topo%available .or. .not. allocated(topo%links)) return
    if (table%row_count() == 0) return
    nl = size(topo%links)
    allocate (omega(nl), eps(nl), none(2, nl), c_omega(nl), c_eps(nl))
    none = 0.0_wp
    do i = 1, nl
      c_omega(i) = table%column_index("omega"//topo%links(i)%name)
      c_eps(i) = table%column_index("eps"//topo%links(i)%name)
    end do
    ! the points (the same at every row: the topology's) and where their positions are
    call points_from_sketch(topo, table, 1, drawing, error)
    if (allocated(error)) return
    allocate (cx(size(drawing%points)), cy(size(drawing%points)), image(size(drawing%points)))
    do ip = 1, size(drawing%points)
      cx(ip) = table%column_index("x_"//trim(drawing%points(ip)%name))
      cy(ip) = table%column_index("y_"//trim(drawing%points(ip)%name))
    end do
    known = field_topology(topo, drawing, table)
    do k = 1, table%row_count()
      do ip = 1, size(drawing%points)
        drawing%points(ip)%p = [table%rows(cx(ip), k), table%rows(cy(ip), k)]
      end do
      do i = 1, nl
        omega(i) = 0.0_wp
        if (c_omega(i) > 0) omega(i) = table%rows(c_omega(i), k)
        eps(i) = 0.0_wp
        if (c_eps(i) > 0) eps(i) = table%rows(c_eps(i), k)
      end do
      call solve_fields(topo, drawing, table, k, omega, eps, .false., none, v0, residual, known)
      call solve_fields(topo, drawing, table, k, omega, eps, .true., v0, a0, residual, known)
      call point_images(topo, drawing, omega, eps, v0, .false., v, known)
      call point_images(topo, drawing, omega, eps, a0, .true., a, known)
      if (k == 1) then
        do ip = 1, size(drawing%points)
          image(ip) = named_image(v, drawing%points(ip)%name)
        end do
      end if
      do ip = 1, size(drawing%points)
        associate (pt => drawing%points(ip))
          iv = image(ip)
          if (iv == 0) cycle
          if (pt%kind == point_pivot) then
            call table%put_velocity(k, trim(pt%name), [0.0_wp, 0.0_wp])
            call table%put_acceleration(k, trim(pt%name), [0.0_wp, 0.0_wp])
          else
            call table%put_velocity(k, trim(pt%name), v(iv)%v)
            if (pt%kind /= point_com) call table%put_acceleration(k, trim(pt%name), a(iv)%v)
          end if
        end associate
      end do
    end do
  contains
    !> Index of the image named `name` (0: none).
    pure integer function named_image(images, name)
      type(plan_vector_t), intent(in) :: images(:)
      character(*), intent(in) :: name
      integer :: j
      named_image = 0
      do j = 1, size(images)
        if (images(j)%name == name) then
          named_image = j
          return
        end if
      end do
    end function named_image
  end subroutine add_point_motion


end module kinetostat_point_motion
