!> The mechanism at one step as an ASCII DXF drawing (`--format dxf --at K`) for CAD
!> programs (LibreCAD, ...): AutoCAD R12 entities only (LINE, CIRCLE, TEXT) in millimetres in
!> the mechanism's position frame (x right, y up; 1 m = 1000 mm), on layers
!> LINKS (bodies: bars, plates, blocks, cylinders, rods), JOINTS (joints and pivots as circles,
!> centres of mass), GUIDES (the guides on the frame), FORCES (every force as an arrow at one
!> force scale, moments as text), TEXT (point names and force values). The same drawing as
!> the --at sheet (kinetostat_drawing), without the sheet's turn.
module kinetostat_dxf
  use kinetostat_kinds, only: wp
  use kinetostat_format, only: fixed_number, short_number
  use kinetostat_text, only: int_str
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_escape, only: dxf_text
  use kinetostat_drawing, only: drawing_t, point_pivot, point_com, point_plain, body_bar, body_block, body_cylinder, &
    body_rod
  implicit none
  private
  public :: write_dxf

  !> The layers and their colours (AutoCAD colour index).
  character(*), parameter :: layer_names(*) = [character(len=6) :: "LINKS", "JOINTS", "GUIDES", "FORCES", "TEXT"]
  integer, parameter :: layer_colours(*) = [7, 5, 8, 1, 3]
  !> The file's head up to the layer table: group codes and their values (R12, units mm).
  integer, parameter :: head_codes(*) = [0, 2, 9, 1, 9, 70, 0, 0, 2, 0, 2, 70]
  character(*), parameter :: head_values(*) = [character(len=9) :: "SECTION", "HEADER", "$ACADVER", "AC1009", &
    "$INSUNITS", "4", "ENDSEC", "SECTION", "TABLES", "TABLE", "LAYER", "5"]
  !> After the layer table, the start of the entities.
  integer, parameter :: entities_codes(*) = [0, 0, 0, 2]
  character(*), parameter :: entities_values(*) = [character(len=8) :: "ENDTAB", "ENDSEC", "SECTION", "ENTITIES"]

contains

  !> The DXF of `drawing` (m, N); `title` goes into a TEXT under the drawing.
  pure subroutine write_dxf(title, drawing, out)
    !> Title line (mechanism, deck, step).
    character(*), intent(in) :: title
    !> The mechanism at the step, with its forces.
    type(drawing_t), intent(in) :: drawing
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    real(wp) :: lo(2), hi(2), size_mm, fmax, fscale, h, p(2), u(2), n(2), a(2), b(2)
    integer :: i, j
    lo = huge(1.0_wp)
    hi = -huge(1.0_wp)
    do i = 1, size(drawing%points)
      lo = min(lo, mm(drawing%points(i)%p))
      hi = max(hi, mm(drawing%points(i)%p))
    end do
    if (size(drawing%points) == 0) then
      lo = 0.0_wp
      hi = 1.0_wp
    end if
    size_mm = max(maxval(hi - lo), 1.0_wp)
    h = 0.02_wp * size_mm
    fmax = 0.0_wp
    do i = 1, size(drawing%forces)
      fmax = max(fmax, norm2(drawing%forces(i)%f))
    end do
    fscale = 0.0_wp
    if (fmax > 0.0_wp) fscale = 0.25_wp * size_mm / fmax

    do i = 1, size(head_codes)
      call pair(out, head_codes(i), trim(head_values(i)))
    end do
    do i = 1, size(layer_names)
      call pair(out, 0, "LAYER")
      call pair(out, 2, trim(layer_names(i)))
      call pair(out, 70, "0")
      call pair(out, 62, short_int(layer_colours(i)))
      call pair(out, 6, "CONTINUOUS")
    end do
    do i = 1, size(entities_codes)
      call pair(out, entities_codes(i), trim(entities_values(i)))
    end do
    ! bodies
    do i = 1, size(drawing%bodies)
      associate (bd => drawing%bodies(i))
        select case (bd%kind)
        case (body_bar)
          do j = 1, size(bd%points) - 1
            call line(out, "LINKS", mm(drawing%points(bd%points(j))%p), mm(drawing%points(bd%points(j + 1))%p))
          end do
          if (size(bd%points) > 2) call line(out, "LINKS", mm(drawing%points(bd%points(size(bd%points)))%p), &
            mm(drawing%points(bd%points(1))%p))
        case (body_block)
          p = mm(drawing%points(bd%points(1))%p)
          u = [cos(bd%angle), sin(bd%angle)] * 1.5_wp * h
          n = [-u(2), u(1)] * 0.6_wp
          call line(out, "LINKS", p - u - n, p + u - n)
          call line(out, "LINKS", p + u - n, p + u + n)
          call line(out, "LINKS", p + u + n, p - u + n)
          call line(out, "LINKS", p - u + n, p - u - n)
        case (body_cylinder)
          u = [cos(bd%angle), sin(bd%angle)]
          n = [-u(2), u(1)] * 0.6_wp * h
          a = mm(bd%anchor)
          b = mm(bd%anchor + bd%length * u)
          call line(out, "LINKS", a + n, b + n)
          call line(out, "LINKS", a - n, b - n)
          call line(out, "LINKS", a + n, a - n)
        case (body_rod)
          u = [cos(bd%angle), sin(bd%angle)]
          call line(out, "LINKS", mm(bd%anchor + bd%reach(1) * u), mm(bd%anchor + bd%reach(2) * u))
        case default
          continue
        end select
      end associate
    end do
    ! guides on the frame
    do i = 1, size(drawing%guides)
      associate (g => drawing%guides(i))
        u = [cos(g%angle), sin(g%angle)] * g%half_length
        call line(out, "GUIDES", mm(g%p - u), mm(g%p + u))
      end associate
    end do
    ! joints, pivots, centres of mass, with their names
    do i = 1, size(drawing%points)
      associate (pt => drawing%points(i))
        if (pt%kind == point_plain) cycle
        p = mm(pt%p)
        if (pt%kind == point_com) then
          call circle(out, "JOINTS", p, 0.3_wp * h)
        else
          call circle(out, "JOINTS", p, 0.5_wp * h)
        end if
        if (pt%kind == point_pivot) then
          call line(out, "JOINTS", p, p + [-h, -1.5_wp * h])
          call line(out, "JOINTS", p, p + [h, -1.5_wp * h])
          call line(out, "JOINTS", p + [-1.5_wp * h, -1.5_wp * h], p + [1.5_wp * h, -1.5_wp * h])
        end if
        call text(out, "TEXT", p + [0.7_wp * h, 0.7_wp * h], h, trim(pt%name))
      end associate
    end do
    ! forces as arrows at one scale, labelled with their values
    if (allocated(drawing%forces) .and. fscale > 0.0_wp) then
      do i = 1, size(drawing%forces)
        associate (f => drawing%forces(i))
          if (norm2(f%f) * fscale < 1.0e-6_wp * size_mm) cycle
          a = mm(f%at)
          b = a + fscale * f%f
          u = (b - a) / norm2(b - a)
          n = [-u(2), u(1)]
          call line(out, "FORCES", a, b)
          call line(out, "FORCES", b, b - 1.2_wp * h * u + 0.4_wp * h * n)
          call line(out, "FORCES", b, b - 1.2_wp * h * u - 0.4_wp * h * n)
          call text(out, "TEXT", b + 0.5_wp * h * u, 0.8_wp * h, trim(f%name)//" = "//short_number(norm2(f%f))//" N")
        end associate
      end do
    end if
    do i = 1, size(drawing%moments)
      associate (m => drawing%moments(i))
        call text(out, "FORCES", mm(m%at) + [0.7_wp * h, -1.5_wp * h], 0.8_wp * h, trim(m%name)//" = "// &
          short_number(m%value)//" N*m")
      end associate
    end do
    call text(out, "TEXT", [lo(1), lo(2) - 4.0_wp * h], h, title)
    call pair(out, 0, "ENDSEC")
    call pair(out, 0, "EOF")
  contains
    !> m -> mm.
    pure function mm(x) result(y)
      real(wp), intent(in) :: x(2)
      real(wp) :: y(2)
      y = 1000.0_wp * x
    end function mm
  end subroutine write_dxf

  !> One group: its code line and its value line.
  pure subroutine pair(out, code, value)
    type(text_buffer_t), intent(inout) :: out
    integer, intent(in) :: code
    character(*), intent(in) :: value
    call out%put(short_int(code))
    call out%put(value)
  end subroutine pair

  !> An integer as text.
  pure function short_int(i) result(t)
    integer, intent(in) :: i
    character(len=:), allocatable :: t
    t = int_str(i)
  end function short_int

  !> A coordinate, mm (6 decimals: 1 nm).
  pure function num(x) result(t)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: t
    t = fixed_number(x, 6)
  end function num

  !> The head of an entity: its kind, layer and first point (z = 0).
  pure subroutine entity(out, kind, layer, p)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: kind, layer
    real(wp), intent(in) :: p(2)
    call pair(out, 0, kind)
    call pair(out, 8, layer)
    call pair(out, 10, num(p(1)))
    call pair(out, 20, num(p(2)))
    call pair(out, 30, "0.0")
  end subroutine entity

  !> LINE from a to b on `layer`.
  pure subroutine line(out, layer, a, b)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: layer
    real(wp), intent(in) :: a(2), b(2)
    call entity(out, "LINE", layer, a)
    call pair(out, 11, num(b(1)))
    call pair(out, 21, num(b(2)))
    call pair(out, 31, "0.0")
  end subroutine line

  !> CIRCLE about c of radius r on `layer`.
  pure subroutine circle(out, layer, c, r)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: layer
    real(wp), intent(in) :: c(2), r
    call entity(out, "CIRCLE", layer, c)
    call pair(out, 40, num(r))
  end subroutine circle

  !> TEXT at p of height h on `layer`: its value through the escaper (ASCII, one line).
  pure subroutine text(out, layer, p, h, value)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: layer, value
    real(wp), intent(in) :: p(2), h
    call entity(out, "TEXT", layer, p)
    call pair(out, 40, num(h))
    call pair(out, 1, dxf_text(value))
  end subroutine text

end module kinetostat_dxf
