!> SVG primitives: pure functions that return one element as text (lines, paths, circles,
!> rectangles, text, arrows) in the sheet's user units (mm), plus the document frame.
!> Every number goes through kinetostat_format's fixed_number with `coord_decimals`
!> decimals, so the same drawing always gives the same bytes. Styling is by the CSS
!> classes of `svg_open`'s style sheet (embedded: the document needs no other file).
module kinetostat_svg
  use kinetostat_kinds, only: wp
  use kinetostat_format, only: fixed_number
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_escape, only: xml_escape
  implicit none
  private
  public :: svg_open, svg_close, svg_line, svg_path, svg_polyline_d, svg_circle, svg_rect, svg_text, &
    svg_polygon, svg_group_open, svg_group_close, xml_escape, coord, palette_colour, &
    coord_decimals

  !> Decimals of every coordinate, mm (0.01 mm: far below what a printer or a screen shows).
  integer, parameter :: coord_decimals = 2
  !> Colours of data series, in order (a colour-blind-safe qualitative palette); series
  !> beyond the list reuse it with a dash pattern (see palette_colour).
  character(*), parameter :: palette(*) = [character(len=7) :: "#1f77b4", "#d62728", "#2ca02c", &
    "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"]
  !> The style sheet of every sheet: sizes in mm (user units).
  character(*), parameter :: style_lines(*) = [character(len=100) :: &
    "text { font-family: sans-serif; fill: #000000; }", &
    ".title { font-size: 3.3px; font-weight: bold; }", &
    ".subtitle { font-size: 3px; }", &
    ".heading { font-size: 3.2px; font-weight: bold; }", &
    ".label { font-size: 2.8px; }", &
    ".small { font-size: 2.4px; fill: #333333; }", &
    ".num { font-size: 2.2px; fill: #222222; }", &
    ".note { font-size: 2.6px; font-style: italic; fill: #444444; }", &
    ".panel { fill: none; stroke: #999999; stroke-width: 0.25; }", &
    ".axis { fill: none; stroke: #000000; stroke-width: 0.3; }", &
    ".faint { fill: none; stroke: #999999; stroke-width: 0.2; }", &
    ".grid { fill: none; stroke: #e0e0e0; stroke-width: 0.15; }", &
    ".ray { fill: none; stroke: #c8c8c8; stroke-width: 0.12; }", &
    ".mean { fill: none; stroke: #000000; stroke-width: 0.3; stroke-dasharray: 1.5 1; }", &
    ".scale { fill: none; stroke: #000000; stroke-width: 0.35; }", &
    ".origin { fill: #ffffff; stroke: #000000; stroke-width: 0.3; }", &
    ".link { fill: #f4f4f4; stroke: #000000; stroke-width: 0.5; stroke-linejoin: round; }", &
    ".frame { fill: none; stroke: #000000; stroke-width: 0.4; }", &
    ".hatch { fill: none; stroke: #000000; stroke-width: 0.2; }", &
    ".joint { fill: #ffffff; stroke: #000000; stroke-width: 0.35; }", &
    ".com { fill: #000000; stroke: none; }", &
    ".hodograph { fill: none; stroke: #1f77b4; stroke-width: 0.45; stroke-linejoin: round; }", &
    ".point { fill: #1f77b4; stroke: none; }"]

contains

  !> A coordinate or length in user units (mm), with `coord_decimals` decimals.
  pure function coord(x) result(text)
    !> Value, mm.
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    text = fixed_number(x, coord_decimals)
  end function coord

  !> Colour `i` (1-based) of the series palette, and its dash pattern ("" for the first
  !> round through the palette, a dash pattern after that).
  pure subroutine palette_colour(i, colour, dash)
    !> Series number, 1-based.
    integer, intent(in) :: i
    !> "#rrggbb".
    character(len=7), intent(out) :: colour
    !> stroke-dasharray value, or "".
    character(len=:), allocatable, intent(out) :: dash
    integer :: round
    colour = palette(modulo(i - 1, size(palette)) + 1)
    round = (i - 1) / size(palette)
    select case (round)
    case (0)
      dash = ""
    case (1)
      dash = "2 1"
    case default
      dash = "0.6 0.6"
    end select
  end subroutine palette_colour

  !> The start of a document `width` x `height` mm with its title, description, style sheet
  !> and a white background.
  pure subroutine svg_open(out, width, height, title, description)
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Sheet width, mm.
    real(wp), intent(in) :: width
    !> Sheet height, mm.
    real(wp), intent(in) :: height
    !> Document title (plain text).
    character(*), intent(in) :: title
    !> Description (plain text): what the sheet shows and how to read its data back.
    character(*), intent(in) :: description
    call out%put('<?xml version="1.0" encoding="UTF-8"?>')
    call out%put('<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="'//coord(width)//'mm" height="'// &
      coord(height)//'mm" viewBox="0 0 '//coord(width)//" "//coord(height)//'">')
    call out%put("<title>"//xml_escape(title)//"</title>")
    call out%put("<desc>"//xml_escape(description)//"</desc>")
    call out%put("<style>")
    call out%put_lines(style_lines)
    call out%put("</style>")
    call out%put('<rect x="0" y="0" width="'//coord(width)//'" height="'//coord(height)//'" fill="#ffffff"/>')
  end subroutine svg_open

  !> The end of the document.
  pure subroutine svg_close(out)
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    call out%put("</svg>")
  end subroutine svg_close

  !> `<g ...>` with the given attributes.
  pure function svg_group_open(attributes) result(text)
    !> Attributes (already escaped), e.g. 'id="x"'.
    character(*), intent(in) :: attributes
    character(len=:), allocatable :: text
    if (len(attributes) > 0) then
      text = "<g "//attributes//">"
    else
      text = "<g>"
    end if
  end function svg_group_open

  !> `</g>`.
  pure function svg_group_close() result(text)
    character(len=:), allocatable :: text
    text = "</g>"
  end function svg_group_close

  !> A straight line from (x1, y1) to (x2, y2), mm.
  pure function svg_line(x1, y1, x2, y2, attributes) result(text)
    !> Start, mm.
    real(wp), intent(in) :: x1, y1
    !> End, mm.
    real(wp), intent(in) :: x2, y2
    !> Attributes (already escaped), e.g. 'class="axis"'.
    character(*), intent(in) :: attributes
    character(len=:), allocatable :: text
    text = '<line x1="'//coord(x1)//'" y1="'//coord(y1)//'" x2="'//coord(x2)//'" y2="'//coord(y2)//'" '// &
      attributes//"/>"
  end function svg_line

  !> The path data of a polyline through the points: "M x1 y1 L x2 y2 ...", mm.
  pure function svg_polyline_d(x, y) result(d)
    !> Abscissae, mm.
    real(wp), intent(in) :: x(:)
    !> Ordinates, mm (same size).
    real(wp), intent(in) :: y(:)
    character(len=:), allocatable :: d
    character(len=:), allocatable :: piece
    integer :: k, n
    ! filled in place (a growing concatenation would copy the path once per point)
    allocate (character(len=64 * size(x) + 1) :: d)
    n = 0
    do k = 1, size(x)
      if (k == 1) then
        piece = "M "//coord(x(k))//" "//coord(y(k))
      else
        piece = " L "//coord(x(k))//" "//coord(y(k))
      end if
      if (n + len(piece) > len(d)) d = d//repeat(" ", len(d))
      d(n + 1:n + len(piece)) = piece
      n = n + len(piece)
    end do
    d = d(1:n)
  end function svg_polyline_d

  !> A path with data `d`.
  pure function svg_path(d, attributes) result(text)
    !> Path data.
    character(*), intent(in) :: d
    !> Attributes (already escaped).
    character(*), intent(in) :: attributes
    character(len=:), allocatable :: text
    text = '<path d="'//d//'" '//attributes//"/>"
  end function svg_path

  !> A closed polygon through the points, mm.
  pure function svg_polygon(x, y, attributes) result(text)
    !> Abscissae, mm.
    real(wp), intent(in) :: x(:)
    !> Ordinates, mm.
    real(wp), intent(in) :: y(:)
    !> Attributes (already escaped).
    character(*), intent(in) :: attributes
    character(len=:), allocatable :: text
    integer :: k
    text = '<polygon points="'
    do k = 1, size(x)
      if (k > 1) text = text//" "
      text = text//coord(x(k))//","//coord(y(k))
    end do
    text = text//'" '//attributes//"/>"
  end function svg_polygon

  !> A circle of radius r about (cx, cy), mm.
  pure function svg_circle(cx, cy, r, attributes) result(text)
    !> Centre, mm.
    real(wp), intent(in) :: cx, cy
    !> Radius, mm.
    real(wp), intent(in) :: r
    !> Attributes (already escaped).
    character(*), intent(in) :: attributes
    character(len=:), allocatable :: text
    text = '<circle cx="'//coord(cx)//'" cy="'//coord(cy)//'" r="'//coord(r)//'" '//attributes//"/>"
  end function svg_circle

  !> A rectangle with its top-left corner at (x, y), mm.
  pure function svg_rect(x, y, width, height, attributes) result(text)
    !> Top-left corner, mm.
    real(wp), intent(in) :: x, y
    !> Width, mm.
    real(wp), intent(in) :: width
    !> Height, mm.
    real(wp), intent(in) :: height
    !> Attributes (already escaped).
    character(*), intent(in) :: attributes
    character(len=:), allocatable :: text
    text = '<rect x="'//coord(x)//'" y="'//coord(y)//'" width="'//coord(width)//'" height="'//coord(height)// &
      '" '//attributes//"/>"
  end function svg_rect

  !> Text whose baseline starts (or is anchored, see attributes) at (x, y), mm.
  pure function svg_text(x, y, text_value, attributes) result(text)
    !> Anchor point, mm.
    real(wp), intent(in) :: x, y
    !> Plain text (escaped here).
    character(*), intent(in) :: text_value
    !> Attributes (already escaped), e.g. 'class="label" text-anchor="middle"'.
    character(*), intent(in) :: attributes
    character(len=:), allocatable :: text
    text = '<text x="'//coord(x)//'" y="'//coord(y)//'" '//attributes//">"//xml_escape(text_value)//"</text>"
  end function svg_text

end module kinetostat_svg
