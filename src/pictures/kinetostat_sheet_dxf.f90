!> The DXF writer of the drawing model (kinetostat_sheet): the sheet as an ASCII DXF of AutoCAD
!> R12 entities that LibreCAD, КОМПАС or any CAD program opens, in millimetres of the paper
!> (x right, y up from the sheet's lower left corner: y_dxf = height - y_sheet; the limits
!> and extents are the paper's).
!> - HEADER ($ACADVER AC1009, $INSUNITS 4 = mm, $LIMMIN/$LIMMAX and $EXTMIN/$EXTMAX = the
!>   paper), TABLES (line types CONTINUOUS and DASHED; the model's layers with their colours),
!>   ENTITIES, EOF.
!> - line -> LINE; polyline -> POLYLINE (its VERTEXes, SEQEND), a stroked polygon -> a closed
!>   POLYLINE (flag 70 = 1), rect -> LINEs; a filled dark polygon of 3 or 4 corners (an
!>   arrowhead) also a SOLID; circle -> CIRCLE; arc -> ARC; text -> TEXT (height 0.7 of
!>   the font size, the cap height; alignment 72 = 0/1/2 with its point in 11/21; rotation);
!>   a group -> a comment (999) "kinetostat group CLASS NAME=VALUE ...", its data attributes
!>   (the mechanism's view: where its position frame sits on the sheet, for read-back).
!> - Colours: an entity's colour as the nearest AutoCAD index of a small table, else the
!>   layer's; dashed classes and dash overrides on line type DASHED.
!> - Text: the typeset runs as one line (kinetostat_typeset's plain_text: F21, a_CB^τ),
!>   every character beyond ASCII as AutoCAD's \U+XXXX (Φ -> \U+03A6), so the file is ASCII.
!>   Every text goes through `escaped`, the program's DXF escaper (kinetostat_escape's
!>   dxf_text: also control characters as \n, \xNN, a caret as "^ ").
module kinetostat_sheet_dxf
  use kinetostat_kinds, only: wp
  use kinetostat_format, only: fixed_number
  use kinetostat_text, only: int_str
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_typeset, only: plain_text
  use kinetostat_escape, only: escaped => dxf_text
  use kinetostat_sheet, only: sheet_t, entity_t, entity_line, entity_polyline, entity_polygon, entity_rect, &
    entity_circle, entity_arc, entity_text, entity_group, anchor_middle, anchor_end, layer_names, line_classes
  implicit none
  private
  public :: write_sheet_dxf

  !> Colours of the layers (AutoCAD colour index), in the order of layer_names.
  integer, parameter :: layer_colours(*) = [7, 5, 8, 1, 3, 5, 1, 3, 6, 7, 7, 8, 7]
  !> Colours the sheets use and their AutoCAD indices.
  character(*), parameter :: known_colours(*) = [character(len=7) :: "#d62728", "#2ca02c", "#1f77b4", "#8c564b", &
    "#ff7f0e", "#9467bd", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22", "#555555", "#777777", "#999999", "#c8c8c8", &
    "#e0e0e0", "#000000", "#222222", "#333333", "#444444"]
  integer, parameter :: known_indices(*) = [1, 3, 5, 34, 30, 6, 6, 4, 8, 2, 8, 8, 8, 9, 9, 7, 7, 7, 7]

contains

  !> The DXF of `sheet`.
  pure subroutine write_sheet_dxf(sheet, out)
    !> The sheet.
    type(sheet_t), intent(in) :: sheet
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    integer :: i, k, n
    real(wp) :: h
    character(len=:), allocatable :: note
    h = sheet%paper%height
    call pair(out, 999, escaped(sheet%title))
    call pair(out, 0, "SECTION")
    call pair(out, 2, "HEADER")
    call pair(out, 9, "$ACADVER")
    call pair(out, 1, "AC1009")
    call pair(out, 9, "$INSUNITS")
    call pair(out, 70, "4")
    call point_var(out, "$LIMMIN", 0.0_wp, 0.0_wp)
    call point_var(out, "$LIMMAX", sheet%paper%width, h)
    call point_var(out, "$EXTMIN", 0.0_wp, 0.0_wp)
    call point_var(out, "$EXTMAX", sheet%paper%width, h)
    call pair(out, 0, "ENDSEC")
    call pair(out, 0, "SECTION")
    call pair(out, 2, "TABLES")
    call pair(out, 0, "TABLE")
    call pair(out, 2, "LTYPE")
    call pair(out, 70, "2")
    call pair(out, 0, "LTYPE")
    call pair(out, 2, "CONTINUOUS")
    call pair(out, 70, "0")
    call pair(out, 3, "Solid line")
    call pair(out, 72, "65")
    call pair(out, 73, "0")
    call pair(out, 40, "0.0")
    call pair(out, 0, "LTYPE")
    call pair(out, 2, "DASHED")
    call pair(out, 70, "0")
    call pair(out, 3, "Dashed __ __ __")
    call pair(out, 72, "65")
    call pair(out, 73, "2")
    call pair(out, 40, "2.5")
    call pair(out, 49, "1.5")
    call pair(out, 49, "-1.0")
    call pair(out, 0, "ENDTAB")
    call pair(out, 0, "TABLE")
    call pair(out, 2, "LAYER")
    call pair(out, 70, int_str(size(layer_names)))
    do i = 1, size(layer_names)
      call pair(out, 0, "LAYER")
      call pair(out, 2, trim(layer_names(i)))
      call pair(out, 70, "0")
      call pair(out, 62, int_str(layer_colours(i)))
      call pair(out, 6, "CONTINUOUS")
    end do
    call pair(out, 0, "ENDTAB")
    call pair(out, 0, "ENDSEC")
    call pair(out, 0, "SECTION")
    call pair(out, 2, "ENTITIES")
    do i = 1, sheet%count
      associate (e => sheet%items(i))
        select case (e%kind)
        case (entity_line)
          call line(out, h, e, [e%x(1), e%y(1)], [e%x(2), e%y(2)])
        case (entity_polyline)
          call polyline(out, h, e, .false.)
        case (entity_polygon)
          n = size(e%x)
          if (stroked(e)) call polyline(out, h, e, .true.)
          if (dark_fill(e) .and. (n == 3 .or. n == 4)) call solid(out, h, e)
        case (entity_rect)
          if (stroked(e)) then
            call line(out, h, e, [e%x(1), e%y(1)], [e%x(2), e%y(1)])
            call line(out, h, e, [e%x(2), e%y(1)], [e%x(2), e%y(2)])
            call line(out, h, e, [e%x(2), e%y(2)], [e%x(1), e%y(2)])
            call line(out, h, e, [e%x(1), e%y(2)], [e%x(1), e%y(1)])
          end if
        case (entity_circle)
          call head(out, h, e, "CIRCLE", [e%x(1), e%y(1)])
          call pair(out, 40, num(e%radius))
        case (entity_arc)
          ! DXF arcs run counterclockwise from the start angle to the end angle
          call head(out, h, e, "ARC", [e%x(1), e%y(1)])
          call pair(out, 40, num(e%radius))
          if (e%sweep >= 0.0_wp) then
            call pair(out, 50, num(modulo(e%start, 360.0_wp)))
            call pair(out, 51, num(modulo(e%start + e%sweep, 360.0_wp)))
          else
            call pair(out, 50, num(modulo(e%start + e%sweep, 360.0_wp)))
            call pair(out, 51, num(modulo(e%start, 360.0_wp)))
          end if
        case (entity_text)
          call head(out, h, e, "TEXT", [e%x(1), e%y(1)])
          call pair(out, 40, num(0.7_wp * e%size))
          call pair(out, 1, escaped(plain_text(e%runs)))
          if (e%rotation /= 0.0_wp) call pair(out, 50, num(-e%rotation))
          if (e%anchor == anchor_middle .or. e%anchor == anchor_end) then
            call pair(out, 72, merge("1", "2", e%anchor == anchor_middle))
            call pair(out, 11, num(e%x(1)))
            call pair(out, 21, num(h - e%y(1)))
            call pair(out, 31, "0.0")
          end if
        case (entity_group)
          note = "kinetostat group "//e%class
          if (allocated(e%data_names)) then
            do k = 1, size(e%data_names)
              note = note//" "//trim(e%data_names(k))//"="//escaped(trim(e%data_values(k)))
            end do
          end if
          call pair(out, 999, note)
        case default
          continue
        end select
      end associate
    end do
    call pair(out, 0, "ENDSEC")
    call pair(out, 0, "EOF")
  end subroutine write_sheet_dxf

  !> A header variable holding a 2-D point.
  pure subroutine point_var(out, name, x, y)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: name
    real(wp), intent(in) :: x, y
    call pair(out, 9, name)
    call pair(out, 10, num(x))
    call pair(out, 20, num(y))
  end subroutine point_var
  !> An entity's kind, layer, colour, line type and first point.
  pure subroutine head(out, h, e, kind, p)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: h
    type(entity_t), intent(in) :: e
    character(*), intent(in) :: kind
    real(wp), intent(in) :: p(2)
    integer :: colour
    call pair(out, 0, kind)
    call pair(out, 8, trim(layer_names(e%layer)))
    colour = entity_colour(e)
    if (colour > 0) call pair(out, 62, int_str(colour))
    if (dashed(e)) call pair(out, 6, "DASHED")
    call pair(out, 10, num(p(1)))
    call pair(out, 20, num(h - p(2)))
    call pair(out, 30, "0.0")
  end subroutine head
  !> LINE from a to b (sheet mm).
  pure subroutine line(out, h, e, a, b)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: h
    type(entity_t), intent(in) :: e
    real(wp), intent(in) :: a(2), b(2)
    call head(out, h, e, "LINE", a)
    call pair(out, 11, num(b(1)))
    call pair(out, 21, num(h - b(2)))
    call pair(out, 31, "0.0")
  end subroutine line
  !> POLYLINE through the entity's points (closed: flag 70 = 1), its VERTEXes and SEQEND, all
  !> on its layer.
  pure subroutine polyline(out, h, e, closed)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: h
    type(entity_t), intent(in) :: e
    logical, intent(in) :: closed
    integer :: k, colour
    call pair(out, 0, "POLYLINE")
    call pair(out, 8, trim(layer_names(e%layer)))
    colour = entity_colour(e)
    if (colour > 0) call pair(out, 62, int_str(colour))
    if (dashed(e)) call pair(out, 6, "DASHED")
    call pair(out, 66, "1")
    call pair(out, 10, "0.0")
    call pair(out, 20, "0.0")
    call pair(out, 30, "0.0")
    call pair(out, 70, merge("1", "0", closed))
    do k = 1, size(e%x)
      call pair(out, 0, "VERTEX")
      call pair(out, 8, trim(layer_names(e%layer)))
      call pair(out, 10, num(e%x(k)))
      call pair(out, 20, num(h - e%y(k)))
      call pair(out, 30, "0.0")
    end do
    call pair(out, 0, "SEQEND")
    call pair(out, 8, trim(layer_names(e%layer)))
  end subroutine polyline

  !> SOLID over a polygon of 3 or 4 corners (a triangle repeats its last corner); DXF's
  !> fourth corner comes before the third.
  pure subroutine solid(out, h, e)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: h
    type(entity_t), intent(in) :: e
    integer :: c(4)
    if (size(e%x) == 3) then
      c = [1, 2, 3, 3]
    else
      c = [1, 2, 4, 3]
    end if
    call head(out, h, e, "SOLID", [e%x(c(1)), e%y(c(1))])
    call pair(out, 11, num(e%x(c(2))))
    call pair(out, 21, num(h - e%y(c(2))))
    call pair(out, 31, "0.0")
    call pair(out, 12, num(e%x(c(3))))
    call pair(out, 22, num(h - e%y(c(3))))
    call pair(out, 32, "0.0")
    call pair(out, 13, num(e%x(c(4))))
    call pair(out, 23, num(h - e%y(c(4))))
    call pair(out, 33, "0.0")
  end subroutine solid

  !> Whether an entity is drawn with a stroke (its own or its class's).
  pure logical function stroked(e)
    type(entity_t), intent(in) :: e
    integer :: i
    stroked = .false.
    if (allocated(e%stroke)) stroked = len(e%stroke) > 0 .and. e%stroke /= "none"
    if (stroked .or. .not. allocated(e%class)) return
    do i = 1, size(line_classes)
      if (line_classes(i)%name == e%class) stroked = line_classes(i)%stroke /= "none"
    end do
  end function stroked

  !> Whether an entity is filled with a dark colour (an arrowhead, a dot).
  pure logical function dark_fill(e)
    type(entity_t), intent(in) :: e
    character(len=:), allocatable :: fill
    integer :: i
    fill = ""
    if (allocated(e%fill)) fill = e%fill
    if (len(fill) == 0 .and. allocated(e%class)) then
      do i = 1, size(line_classes)
        if (line_classes(i)%name == e%class) fill = trim(line_classes(i)%fill)
      end do
    end if
    dark_fill = len(fill) == 7 .and. fill(1:1) == "#"
    if (dark_fill) dark_fill = luminance(fill) < 0.8_wp
  end function dark_fill

  !> Relative luminance of "#rrggbb" (0 black .. 1 white).
  pure real(wp) function luminance(colour)
    character(*), intent(in) :: colour
    luminance = (0.299_wp * hex(colour(2:3)) + 0.587_wp * hex(colour(4:5)) + 0.114_wp * hex(colour(6:7))) / 255.0_wp
  contains
    pure real(wp) function hex(two)
      character(*), intent(in) :: two
      hex = 16 * digit(two(1:1)) + digit(two(2:2))
    end function hex
    pure integer function digit(c)
      character, intent(in) :: c
      digit = index("0123456789abcdef", c) - 1
      if (digit < 0) digit = index("0123456789ABCDEF", c) - 1
      digit = max(digit, 0)
    end function digit
  end function luminance

  !> The AutoCAD colour index of an entity's own stroke or text colour (0: the layer's).
  pure integer function entity_colour(e)
    type(entity_t), intent(in) :: e
    character(len=:), allocatable :: colour
    integer :: i
    entity_colour = 0
    colour = ""
    if (allocated(e%stroke)) colour = e%stroke
    if (len(colour) == 0 .and. allocated(e%fill)) colour = e%fill
    if (len(colour) == 0 .and. allocated(e%class)) then
      do i = 1, size(line_classes)
        if (line_classes(i)%name == e%class) colour = trim(line_classes(i)%stroke)
      end do
    end if
    do i = 1, size(known_colours)
      if (known_colours(i) == colour) entity_colour = known_indices(i)
    end do
  end function entity_colour

  !> Whether an entity is drawn dashed (a dash override, or a dashed class).
  pure logical function dashed(e)
    type(entity_t), intent(in) :: e
    integer :: i
    dashed = .false.
    if (allocated(e%dash)) dashed = len(e%dash) > 0
    if (dashed .or. .not. allocated(e%class)) return
    do i = 1, size(line_classes)
      if (line_classes(i)%name == e%class) dashed = len_trim(line_classes(i)%dash) > 0
    end do
  end function dashed

  !> One group: its code line and its value line.
  pure subroutine pair(out, code, value)
    type(text_buffer_t), intent(inout) :: out
    integer, intent(in) :: code
    character(*), intent(in) :: value
    call out%put(int_str(code))
    call out%put(value)
  end subroutine pair

  !> A coordinate, mm (6 decimals: 1 nm).
  pure function num(x) result(t)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: t
    t = fixed_number(x, 6)
  end function num

end module kinetostat_sheet_dxf
