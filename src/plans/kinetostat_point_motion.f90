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
  use kinetostat_drawing, only: drawing_t, column_value, point_pivot, point_com, points_from_sketch
  use kinetostat_plans_base, only: plan_vector_t
  use kinetostat_plans, only: solve_fields, point_images
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
    type(plan_vector_t), allocatable :: v(:), a(:)
    real(wp), allocatable :: omega(:), eps(:), v0(:, :), a0(:, :), none(:, :)
    real(wp) :: residual
    integer :: k, i, nl, ip, iv
    if (.not. topo%available .or. .not. allocated(topo%links)) return
    nl = size(topo%links)
    allocate (omega(nl), eps(nl), none(2, nl))
    none = 0.0_wp
    do k = 1, table%row_count()
      call points_from_sketch(topo, table, k, drawing, error)
      if (allocated(error)) return
      do i = 1, nl
        omega(i) = column_value(table, "omega"//topo%links(i)%name, k)
        eps(i) = column_value(table, "eps"//topo%links(i)%name, k)
      end do
      call solve_fields(topo, drawing, table, k, omega, eps, .false., none, v0, residual)
      call solve_fields(topo, drawing, table, k, omega, eps, .true., v0, a0, residual)
      call point_images(topo, drawing, omega, eps, v0, .false., v)
      call point_images(topo, drawing, omega, eps, a0, .true., a)
      do ip = 1, size(drawing%points)
        associate (pt => drawing%points(ip))
          iv = named_image(v, pt%name)
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
