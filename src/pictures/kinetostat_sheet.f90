!> The drawing model every sheet of the program draws through: a sheet of an ISO paper size
!> (A4 to A1, portrait or landscape) holding a list of entities in sheet millimetres (x right,
!> y down, origin at the sheet's upper left corner), each on a layer, which two writers turn
!> into a file: kinetostat_sheet_svg (SVG) and kinetostat_sheet_dxf (ASCII DXF, R12 entities).
!>
!> Entities: line, polyline (open), polygon (closed), rectangle, circle, arc, text (typeset
!> runs, kinetostat_typeset), and group marks (a group's data attributes: the SVG's `<g
!> data-...>`, a DXF comment). An arrow is a line and a filled head; hatching is lines.
!> Style: a class (the style sheet below: "link", "axis", "label", "num" ...) with optional
!> overrides (stroke colour, stroke width, fill, dash); a text has a font size (its class's,
!> or its own), an anchor (start, middle, end), a rotation, a colour, bold or italic.
!> Layers (the DXF's; SVG ignores them): LINKS, JOINTS, GUIDES, FORCES, TEXT, VPLAN, APLAN,
!> POLYGONS, LEVER, SCALES, and FRAME (the format's frame, the title block, panels), CHARTS
!> (axes, grids, curves of diagrams and hodographs), PROFILE (a part's outline for CAD: the
!> cam's actual profile). `set_layer` chooses the layer of the entities that follow.
!>
!> Labels: every text takes its box (the measure of kinetostat_typeset, the one the
!> legibility test reads back from the SVG); `place_label` puts a label for a point or an
!> arrow where its box meets no other label and no line drawn so far (the sheet's own
!> entities are the obstacles: every stroke as a band of its width, circles as polygons;
!> the light construction lines of the classes "grid" and "ray" are not), a leader line
!> (class "leader", counted in `leaders`) joining it to its point when it had to move away.
!> So a sheet draws its lines first and its labels last.
!>
!> Usage:
!>   type(sheet_t) :: sheet
!>   call sheet%open(iso_paper("A4", .false.), lang, "title", "description")
!>   call sheet%set_layer(layer_links)
!>   call sheet%line(x1, y1, x2, y2, "link")
!>   call sheet%text(x, y, "F21 = 2043 N", "num", colour="#d62728")     ! typeset: F₂₁
!>   call sheet%place_label("S2", "label", px, py, base, bounds)       ! placed, off the lines
!>   call write_sheet_svg(sheet, out)      ! or write_sheet_dxf(sheet, out)
module kinetostat_sheet
  use kinetostat_kinds, only: wp, pi
  use kinetostat_labels, only: lang_en
  use kinetostat_typeset, only: text_run_t, typeset, plain_runs, runs_extent
  use kinetostat_label_place, only: label_boxes_t
  implicit none
  private
  public :: sheet_t, entity_t, paper_t, iso_paper, paper_fits, course_paper, kinematics_sheets
  public :: entity_line, entity_polyline, entity_polygon, entity_rect, entity_circle, entity_arc, entity_text, &
    entity_group, entity_group_end
  public :: layer_links, layer_joints, layer_guides, layer_forces, layer_text, layer_vplan, layer_aplan, &
    layer_polygons, layer_lever, layer_scales, layer_frame, layer_charts, layer_profile, layer_names
  public :: anchor_start, anchor_middle, anchor_end
  public :: line_classes, line_class_t, text_classes, text_class_t, class_stroke_width, class_font_size, &
    arc_points, text_box, frame_left, frame_margin

  !> Layers.
  integer, parameter :: layer_links = 1, layer_joints = 2, layer_guides = 3, layer_forces = 4, layer_text = 5, &
    layer_vplan = 6, layer_aplan = 7, layer_polygons = 8, layer_lever = 9, layer_scales = 10, layer_frame = 11, &
    layer_charts = 12, layer_profile = 13
  !> Their names, in the order of their numbers.
  character(*), parameter :: layer_names(*) = [character(len=8) :: "LINKS", "JOINTS", "GUIDES", "FORCES", "TEXT", &
    "VPLAN", "APLAN", "POLYGONS", "LEVER", "SCALES", "FRAME", "CHARTS", "PROFILE"]

  !> Entity kinds.
  integer, parameter :: entity_line = 1, entity_polyline = 2, entity_polygon = 3, entity_rect = 4, &
    entity_circle = 5, entity_arc = 6, entity_text = 7, entity_group = 8, entity_group_end = 9

  !> Text anchors: the box begins at x, is centred on x, ends at x.
  integer, parameter :: anchor_start = 1, anchor_middle = 2, anchor_end = 3

  !> The ГОСТ 2.301 frame: 20 mm from the left edge (the binding), 5 mm from the others.
  real(wp), parameter :: frame_left = 20.0_wp, frame_margin = 5.0_wp

  !> ISO 216 sizes A4..A1: short and long sides, mm.
  character(*), parameter :: paper_names(*) = [character(len=2) :: "A4", "A3", "A2", "A1"]
  real(wp), parameter :: paper_short(*) = [210.0_wp, 297.0_wp, 420.0_wp, 594.0_wp]
  real(wp), parameter :: paper_long(*) = [297.0_wp, 420.0_wp, 594.0_wp, 841.0_wp]

  !> A style of lines and areas.
  type :: line_class_t
    character(len=10) :: name = ""
    !> Stroke colour ("none": no stroke).
    character(len=7) :: stroke = "none"
    !> Stroke width, mm.
    real(wp) :: width = 0.0_wp
    !> Fill ("none" or a colour).
    character(len=7) :: fill = "none"
    !> Dash pattern (stroke-dasharray), "" when solid.
    character(len=8) :: dash = ""
    !> Round joins (bodies, curves).
    logical :: round = .false.
  end type line_class_t

  !> The style sheet of lines and areas (the SVG's CSS classes; the DXF's colours and dashes).
  type(line_class_t), parameter :: line_classes(*) = [ &
    line_class_t("paper", "none", 0.0_wp, "#ffffff", "", .false.), &
    line_class_t("panel", "#999999", 0.25_wp, "none", "", .false.), &
    line_class_t("axis", "#000000", 0.3_wp, "none", "", .false.), &
    line_class_t("faint", "#999999", 0.2_wp, "none", "", .false.), &
    line_class_t("grid", "#e0e0e0", 0.15_wp, "none", "", .false.), &
    line_class_t("ray", "#c8c8c8", 0.12_wp, "none", "", .false.), &
    line_class_t("mean", "#000000", 0.3_wp, "none", "1.5 1", .false.), &
    line_class_t("scale", "#000000", 0.35_wp, "none", "", .false.), &
    line_class_t("origin", "#000000", 0.3_wp, "#ffffff", "", .false.), &
    line_class_t("link", "#000000", 0.5_wp, "#f4f4f4", "", .true.), &
    line_class_t("frame", "#000000", 0.4_wp, "none", "", .false.), &
    line_class_t("hatch", "#000000", 0.2_wp, "none", "", .false.), &
    line_class_t("joint", "#000000", 0.35_wp, "#ffffff", "", .false.), &
    line_class_t("com", "none", 0.0_wp, "#000000", "", .false.), &
    line_class_t("hodograph", "#1f77b4", 0.45_wp, "none", "", .true.), &
    line_class_t("point", "none", 0.0_wp, "#1f77b4", "", .false.), &
    line_class_t("leader", "#777777", 0.15_wp, "none", "", .false.), &
    line_class_t("border", "#000000", 0.5_wp, "none", "", .false.), &
    line_class_t("thick", "#000000", 0.5_wp, "none", "", .false.), &
    line_class_t("thin", "#000000", 0.18_wp, "none", "", .false.)]

  !> A style of text.
  type :: text_class_t
    character(len=10) :: name = ""
    !> Font size, mm.
    real(wp) :: size = 2.8_wp
    logical :: bold = .false.
    logical :: italic = .false.
    !> Colour.
    character(len=7) :: fill = "#000000"
  end type text_class_t

  !> The style sheet of texts.
  type(text_class_t), parameter :: text_classes(*) = [ &
    text_class_t("title", 3.3_wp, .true., .false., "#000000"), &
    text_class_t("subtitle", 3.0_wp, .false., .false., "#000000"), &
    text_class_t("heading", 3.2_wp, .true., .false., "#000000"), &
    text_class_t("label", 2.8_wp, .false., .false., "#000000"), &
    text_class_t("small", 2.4_wp, .false., .false., "#333333"), &
    text_class_t("num", 2.2_wp, .false., .false., "#222222"), &
    text_class_t("note", 2.6_wp, .false., .true., "#444444"), &
    text_class_t("cell", 2.0_wp, .false., .false., "#000000")]

  !> A paper size.
  type :: paper_t
    !> "A4" .. "A1".
    character(len=2) :: name = "A4"
    logical :: landscape = .false.
    !> Width and height, mm.
    real(wp) :: width = 210.0_wp, height = 297.0_wp
  contains
    !> The area inside the ГОСТ 2.301 frame: x0, y0, x1, y1, mm.
    procedure :: inside => paper_inside
  end type paper_t

  !> One thing drawn.
  type :: entity_t
    !> entity_* kind.
    integer :: kind = 0
    !> layer_* number.
    integer :: layer = layer_text
    !> Points, mm (line: 2; polyline, polygon: all; rect: the upper left corner and the
    !> lower right one; circle, arc, text: 1, the centre or the anchor).
    real(wp), allocatable :: x(:), y(:)
    !> Circle, arc: radius, mm.
    real(wp) :: radius = 0.0_wp
    !> Arc: start angle and sweep, deg, counterclockwise as the sheet is seen (0 = right).
    real(wp) :: start = 0.0_wp, sweep = 0.0_wp
    !> Style class ("" for none).
    character(len=:), allocatable :: class
    !> Overrides: stroke colour, fill, dash ("" when the class's).
    character(len=:), allocatable :: stroke, fill, dash
    !> Stroke width override, mm (negative: the class's).
    real(wp) :: width = -1.0_wp
    !> Text: the typeset runs.
    type(text_run_t), allocatable :: runs(:)
    !> Text: font size, mm.
    real(wp) :: size = 0.0_wp
    !> Text: anchor_* .
    integer :: anchor = anchor_start
    !> Text: rotation, deg, clockwise on the sheet (SVG's rotate about the anchor).
    real(wp) :: rotation = 0.0_wp
    !> Text: bold, italic (beyond the class's).
    logical :: bold = .false., italic = .false.
    !> Extra attributes for machine checks (SVG data-*; a group's go to the DXF as a comment).
    character(len=32), allocatable :: data_names(:)
    character(len=96), allocatable :: data_values(:)
  end type entity_t

  !> A sheet.
  type :: sheet_t
    type(paper_t) :: paper
    !> lang_en or lang_ru: how labels are typeset.
    integer :: lang = lang_en
    !> Title and description (SVG metadata; the DXF's first comment).
    character(len=:), allocatable :: title, description
    !> The entities, items(1:count).
    type(entity_t), allocatable :: items(:)
    integer :: count = 0
    !> Layer of the entities added next.
    integer :: layer = layer_text
    !> The boxes the texts took.
    type(label_boxes_t) :: boxes
    !> Leader lines drawn by place_label.
    integer :: leaders = 0
  contains
    procedure :: open => sheet_open
    procedure :: set_layer
    procedure :: line
    procedure :: polyline
    procedure :: polygon
    procedure :: rect
    procedure :: circle
    procedure :: arc
    procedure :: arrow
    procedure :: text
    procedure :: place_label
    procedure :: group
    procedure :: end_group
    procedure :: attach
    procedure :: obstacles
  end type sheet_t

contains

  !> Paper `name` ("A4" .. "A1"), portrait or landscape (an unknown name: A4).
  pure function iso_paper(name, landscape) result(paper)
    !> "A4", "A3", "A2" or "A1".
    character(*), intent(in) :: name
    !> Long side across.
    logical, intent(in) :: landscape
    type(paper_t) :: paper
    integer :: i
    i = max(1, findloc(paper_names, name, dim=1))
    paper%name = paper_names(i)
    paper%landscape = landscape
    if (landscape) then
      paper%width = paper_long(i)
      paper%height = paper_short(i)
    else
      paper%width = paper_short(i)
      paper%height = paper_long(i)
    end if
  end function iso_paper

  !> The paper of a course sheet (`kinetostat sheets --paper`): A1, A2, A3 landscape; A4
  !> portrait (ГОСТ 2.301: on A4 the title block stands along the short side only).
  pure function course_paper(name) result(paper)
    !> "A4", "A3", "A2" or "A1".
    character(*), intent(in) :: name
    type(paper_t) :: paper
    paper = iso_paper(name, name /= "A4")
  end function course_paper

  !> How many sheets the course's kinematics takes on paper `name`: one on A1, A2 (three
  !> columns); two on A3 and A4 (kinematics: the plan of positions, the structure, the output
  !> link's diagrams; kinematics-2: the mechanism in the position, the values, the plans).
  pure integer function kinematics_sheets(name)
    !> "A4", "A3", "A2" or "A1".
    character(*), intent(in) :: name
    kinematics_sheets = merge(2, 1, name == "A3" .or. name == "A4")
  end function kinematics_sheets

  !> Whether a content of `width` x `height` mm fits inside the frame of `paper`.
  pure logical function paper_fits(paper, width, height)
    type(paper_t), intent(in) :: paper
    real(wp), intent(in) :: width, height
    real(wp) :: b(4)
    b = paper%inside()
    paper_fits = width <= b(3) - b(1) .and. height <= b(4) - b(2)
  end function paper_fits

  !> The area inside the ГОСТ 2.301 frame: x0, y0, x1, y1, mm.
  pure function paper_inside(self) result(b)
    class(paper_t), intent(in) :: self
    real(wp) :: b(4)
    b = [frame_left, frame_margin, self%width - frame_margin, self%height - frame_margin]
  end function paper_inside

  !> Start an empty sheet.
  pure subroutine sheet_open(self, paper, lang, title, description)
    class(sheet_t), intent(inout) :: self
    !> Its paper.
    type(paper_t), intent(in) :: paper
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Title and description (plain text).
    character(*), intent(in) :: title, description
    self%paper = paper
    self%lang = lang
    self%title = title
    self%description = description
    if (allocated(self%items)) deallocate (self%items)
    allocate (self%items(64))
    self%count = 0
    self%layer = layer_text
    self%leaders = 0
    if (allocated(self%boxes%box)) deallocate (self%boxes%box)
  end subroutine sheet_open

  !> The layer of the entities added next.
  pure subroutine set_layer(self, layer)
    class(sheet_t), intent(inout) :: self
    !> layer_* number.
    integer, intent(in) :: layer
    self%layer = layer
  end subroutine set_layer

  !> Append an entity (its layer the sheet's current one).
  pure subroutine push(self, item)
    class(sheet_t), intent(inout) :: self
    type(entity_t), intent(inout) :: item
    type(entity_t), allocatable :: grown(:)
    integer :: i
    if (.not. allocated(self%items)) allocate (self%items(64))
    if (self%count == size(self%items)) then
      allocate (grown(2 * size(self%items)))
      do i = 1, self%count
        call move_entity(self%items(i), grown(i))
      end do
      call move_alloc(grown, self%items)
    end if
    item%layer = self%layer
    self%count = self%count + 1
    call move_entity(item, self%items(self%count))
  end subroutine push

  !> Move an entity's contents (its allocatable parts without copying).
  pure subroutine move_entity(from, to)
    type(entity_t), intent(inout) :: from
    type(entity_t), intent(inout) :: to
    to%kind = from%kind
    to%layer = from%layer
    if (allocated(from%x)) call move_alloc(from%x, to%x)
    if (allocated(from%y)) call move_alloc(from%y, to%y)
    to%radius = from%radius
    to%start = from%start
    to%sweep = from%sweep
    if (allocated(from%class)) call move_alloc(from%class, to%class)
    if (allocated(from%stroke)) call move_alloc(from%stroke, to%stroke)
    if (allocated(from%fill)) call move_alloc(from%fill, to%fill)
    if (allocated(from%dash)) call move_alloc(from%dash, to%dash)
    to%width = from%width
    if (allocated(from%runs)) call move_alloc(from%runs, to%runs)
    to%size = from%size
    to%anchor = from%anchor
    to%rotation = from%rotation
    to%bold = from%bold
    to%italic = from%italic
    if (allocated(from%data_names)) call move_alloc(from%data_names, to%data_names)
    if (allocated(from%data_values)) call move_alloc(from%data_values, to%data_values)
  end subroutine move_entity

  !> The style parts every drawing primitive takes.
  pure subroutine style(item, class, stroke, width, fill, dash)
    type(entity_t), intent(inout) :: item
    character(*), intent(in), optional :: class, stroke, fill, dash
    real(wp), intent(in), optional :: width
    item%class = text_or_blank(class)
    item%stroke = text_or_blank(stroke)
    item%fill = text_or_blank(fill)
    item%dash = text_or_blank(dash)
    if (present(width)) item%width = width
  end subroutine style

  !> An optional style text, "" when absent.
  pure function text_or_blank(text) result(value)
    character(*), intent(in), optional :: text
    character(len=:), allocatable :: value
    value = ""
    if (present(text)) value = text
  end function text_or_blank

  !> A shape of `kind` through the points (x, y), mm, with its style (and a circle's radius),
  !> appended.
  pure subroutine add_shape(self, kind, x, y, class, stroke, width, fill, dash, radius)
    class(sheet_t), intent(inout) :: self
    !> entity_line, entity_polyline, entity_polygon, entity_rect or entity_circle.
    integer, intent(in) :: kind
    !> The points (a rectangle's two corners, a circle's centre), mm.
    real(wp), intent(in) :: x(:), y(:)
    character(*), intent(in), optional :: class, stroke, fill, dash
    real(wp), intent(in), optional :: width
    !> A circle's radius, mm.
    real(wp), intent(in), optional :: radius
    type(entity_t) :: item
    item%kind = kind
    item%x = x
    item%y = y
    if (present(radius)) item%radius = radius
    call style(item, class, stroke, width, fill, dash)
    call push(self, item)
  end subroutine add_shape

  !> A straight line from (x1, y1) to (x2, y2), mm.
  pure subroutine line(self, x1, y1, x2, y2, class, stroke, width, dash)
    class(sheet_t), intent(inout) :: self
    real(wp), intent(in) :: x1, y1, x2, y2
    !> Style class, stroke colour, dash pattern (optional).
    character(*), intent(in), optional :: class, stroke, dash
    !> Stroke width, mm (optional).
    real(wp), intent(in), optional :: width
    call add_shape(self, entity_line, [x1, x2], [y1, y2], class, stroke, width, dash=dash)
  end subroutine line

  !> An open line through the points (x, y), mm.
  pure subroutine polyline(self, x, y, class, stroke, width, dash)
    class(sheet_t), intent(inout) :: self
    real(wp), intent(in) :: x(:), y(:)
    character(*), intent(in), optional :: class, stroke, dash
    real(wp), intent(in), optional :: width
    call add_shape(self, entity_polyline, x, y, class, stroke, width, dash=dash)
  end subroutine polyline

  !> A closed polygon through the points (x, y), mm.
  pure subroutine polygon(self, x, y, class, stroke, width, fill)
    class(sheet_t), intent(inout) :: self
    real(wp), intent(in) :: x(:), y(:)
    character(*), intent(in), optional :: class, stroke, fill
    real(wp), intent(in), optional :: width
    call add_shape(self, entity_polygon, x, y, class, stroke, width, fill)
  end subroutine polygon

  !> A rectangle with its upper left corner at (x, y), `w` x `h` mm.
  pure subroutine rect(self, x, y, w, h, class, stroke, width, fill)
    class(sheet_t), intent(inout) :: self
    real(wp), intent(in) :: x, y, w, h
    character(*), intent(in), optional :: class, stroke, fill
    real(wp), intent(in), optional :: width
    call add_shape(self, entity_rect, [x, x + w], [y, y + h], class, stroke, width, fill)
  end subroutine rect

  !> A circle of radius r about (cx, cy), mm.
  pure subroutine circle(self, cx, cy, r, class, stroke, width, fill)
    class(sheet_t), intent(inout) :: self
    real(wp), intent(in) :: cx, cy, r
    character(*), intent(in), optional :: class, stroke, fill
    real(wp), intent(in), optional :: width
    call add_shape(self, entity_circle, [cx], [cy], class, stroke, width, fill, radius=r)
  end subroutine circle

  !> An arc of radius r about (cx, cy), mm, from `start` deg sweeping `sweep` deg
  !> (counterclockwise as the sheet is seen when positive; 0 deg points right).
  pure subroutine arc(self, cx, cy, r, start, sweep, class, stroke, width)
    class(sheet_t), intent(inout) :: self
    real(wp), intent(in) :: cx, cy, r, start, sweep
    character(*), intent(in), optional :: class, stroke
    real(wp), intent(in), optional :: width
    type(entity_t) :: item
    item%kind = entity_arc
    item%x = [cx]
    item%y = [cy]
    item%radius = r
    item%start = start
    item%sweep = sweep
    call style(item, class, stroke, width)
    call push(self, item)
  end subroutine arc

  !> The points an arc is drawn through (every 5 deg at most, both ends), mm.
  pure subroutine arc_points(item, x, y)
    type(entity_t), intent(in) :: item
    real(wp), allocatable, intent(out) :: x(:), y(:)
    integer :: n, i
    real(wp) :: a
    n = max(2, 1 + ceiling(abs(item%sweep) / 5.0_wp))
    allocate (x(n), y(n))
    do i = 1, n
      a = (item%start + item%sweep * (i - 1) / (n - 1)) * pi / 180.0_wp
      x(i) = item%x(1) + item%radius * cos(a)
      y(i) = item%y(1) - item%radius * sin(a)
    end do
  end subroutine arc_points

  !> An arrow from (x1, y1) to its tip (x2, y2), mm: a shaft `width` mm wide to the base of a
  !> filled head `head` mm long (a shorter arrow is all head), in `colour`.
  pure subroutine arrow(self, x1, y1, x2, y2, colour, width, head)
    class(sheet_t), intent(inout) :: self
    real(wp), intent(in) :: x1, y1, x2, y2
    !> Colour "#rrggbb".
    character(*), intent(in) :: colour
    !> Shaft width, mm.
    real(wp), intent(in) :: width
    !> Head length, mm.
    real(wp), intent(in) :: head
    real(wp) :: length, ux, uy, h, bx, by
    length = hypot(x2 - x1, y2 - y1)
    if (length <= 0.0_wp) return
    ux = (x2 - x1) / length
    uy = (y2 - y1) / length
    h = min(head, length)
    bx = x2 - h * ux
    by = y2 - h * uy
    if (length > h) call self%line(x1, y1, bx, by, stroke=colour, width=width)
    call self%polygon([x2, bx - 0.35_wp * h * uy, bx + 0.35_wp * h * uy], [y2, by + 0.35_wp * h * ux, &
      by - 0.35_wp * h * ux], fill=colour)
  end subroutine arrow

  !> A text at (x, y) (its baseline's start, middle or end by `anchor`), typeset as a label
  !> (kinetostat_typeset) unless `plain`; its box is taken (labels placed later avoid it).
  pure subroutine text(self, x, y, value, class, anchor, size, colour, bold, italic, rotation, plain)
    class(sheet_t), intent(inout) :: self
    !> Anchor point, mm.
    real(wp), intent(in) :: x, y
    !> The text, UTF-8.
    character(*), intent(in) :: value
    !> Text class ("label", "num", "small", "title", ...).
    character(*), intent(in) :: class
    !> anchor_* (default start).
    integer, intent(in), optional :: anchor
    !> Font size, mm (default the class's).
    real(wp), intent(in), optional :: size
    !> Colour (default the class's).
    character(*), intent(in), optional :: colour
    !> Bold, italic.
    logical, intent(in), optional :: bold, italic
    !> Rotation, deg clockwise on the sheet, about the anchor point.
    real(wp), intent(in), optional :: rotation
    !> Written as it is: the deck's path and title, a student's name.
    logical, intent(in), optional :: plain
    type(entity_t) :: item
    logical :: as_is
    as_is = .false.
    if (present(plain)) as_is = plain
    item%kind = entity_text
    item%x = [x]
    item%y = [y]
    if (as_is) then
      item%runs = plain_runs(value)
    else
      item%runs = typeset(value, self%lang)
    end if
    item%class = class
    item%stroke = ""
    item%dash = ""
    item%fill = ""
    if (present(colour)) item%fill = colour
    item%size = class_font_size(class)
    if (present(size)) item%size = size
    if (present(anchor)) item%anchor = anchor
    if (present(bold)) item%bold = bold
    if (present(italic)) item%italic = italic
    if (present(rotation)) item%rotation = rotation
    call self%boxes%reserve_box(text_box(item))
    call push(self, item)
  end subroutine text

  !> The box (x0, y0, x1, y1), mm, of a text entity: the typeset runs' extent at its font
  !> size placed by its anchor; a rotated text's box is the bounding box of the turned one.
  pure function text_box(item) result(b)
    !> A text entity.
    type(entity_t), intent(in) :: item
    real(wp) :: b(4)
    real(wp) :: w, above, below, x0, c, s, cx(4), cy(4)
    integer :: i
    call runs_extent(item%runs, w, above, below)
    w = w * item%size
    select case (item%anchor)
    case (anchor_middle)
      x0 = item%x(1) - 0.5_wp * w
    case (anchor_end)
      x0 = item%x(1) - w
    case default
      x0 = item%x(1)
    end select
    b = [x0, item%y(1) - above * item%size, x0 + w, item%y(1) + below * item%size]
    if (item%rotation /= 0.0_wp) then
      c = cos(item%rotation * pi / 180.0_wp)
      s = sin(item%rotation * pi / 180.0_wp)
      cx = [b(1), b(3), b(1), b(3)]
      cy = [b(2), b(2), b(4), b(4)]
      do i = 1, 4
        associate (dx => cx(i) - item%x(1), dy => cy(i) - item%y(1))
          cx(i) = item%x(1) + c * dx - s * dy
          cy(i) = item%y(1) + s * dx + c * dy
        end associate
      end do
      b = [minval(cx), minval(cy), maxval(cx), maxval(cy)]
    end if
  end function text_box

  !> A label for the point (px, py), mm: placed near it inside `bounds` (x0, y0, x1, y1) where
  !> its box meets no other text and no line drawn so far (kinetostat_label_place, strict),
  !> direction `base` (rad on the sheet, y down) preferred, beside the arrow from `tail` when
  !> given; a thin leader line joins it to its point when it had to go farther (counted in
  !> `leaders`). (tx, ty), when asked, is where its baseline's middle went; `relaxed`, whether
  !> no such spot was left and the label went near a line or its leader line over a label.
  pure subroutine place_label(self, value, class, px, py, base, bounds, tail, colour, italic, size, tx, ty, relaxed, outward)
    class(sheet_t), intent(inout) :: self
    !> The label, typeset.
    character(*), intent(in) :: value
    !> Text class.
    character(*), intent(in) :: class
    !> The point labelled, mm.
    real(wp), intent(in) :: px, py
    !> Preferred direction, rad.
    real(wp), intent(in) :: base
    !> Where the label may go, mm.
    real(wp), intent(in) :: bounds(4)
    !> Tail of the arrow whose tip is the point, mm.
    real(wp), intent(in), optional :: tail(2)
    !> Colour of the text.
    character(*), intent(in), optional :: colour
    !> Italic (a link's number).
    logical, intent(in), optional :: italic
    !> Font size, mm (default the class's).
    real(wp), intent(in), optional :: size
    !> Where the label went (baseline middle), mm.
    real(wp), intent(out), optional :: tx, ty
    !> Whether the label had to go near a line or its leader line over a label.
    logical, intent(out), optional :: relaxed
    !> outward_none (default), outward_leaders or outward_all (kinetostat_label_place).
    integer, intent(in), optional :: outward
    type(entity_t) :: item
    real(wp), allocatable :: sx(:), sy(:), sw(:)
    real(wp) :: w, above, below, qx, qy, e(2), hb(4)
    logical :: leader
    item%kind = entity_text
    item%runs = typeset(value, self%lang)
    item%class = class
    item%stroke = ""
    item%dash = ""
    item%fill = ""
    if (present(colour)) item%fill = colour
    if (present(italic)) item%italic = italic
    item%size = class_font_size(class)
    if (present(size)) item%size = size
    item%anchor = anchor_middle
    call runs_extent(item%runs, w, above, below)
    call self%obstacles([bounds(1) - 2.0_wp, bounds(2) - 2.0_wp, bounds(3) + 2.0_wp, bounds(4) + 2.0_wp], sx, sy, sw)
    call self%boxes%place_box(w * item%size, above * item%size, below * item%size, px, py, base, sx, sy, sw, bounds, &
      .true., qx, qy, leader, tail, relaxed, outward)
    if (leader) then
      hb = [qx - 0.5_wp * w * item%size, qy - above * item%size, qx + 0.5_wp * w * item%size, qy + below * item%size]
      e = [max(hb(1), min(hb(3), px)), max(hb(2), min(hb(4), py))]
      call self%line(px, py, e(1), e(2), "leader")
      self%leaders = self%leaders + 1
    end if
    item%x = [qx]
    item%y = [qy]
    call push(self, item)
    if (present(tx)) tx = qx
    if (present(ty)) ty = qy
  end subroutine place_label

  !> Start a group whose data attributes follow (attach); entities up to end_group are in it.
  pure subroutine group(self, class)
    class(sheet_t), intent(inout) :: self
    !> Its class ("mechanism").
    character(*), intent(in) :: class
    type(entity_t) :: item
    item%kind = entity_group
    call style(item, class)
    call push(self, item)
  end subroutine group

  !> End the group begun last.
  pure subroutine end_group(self)
    class(sheet_t), intent(inout) :: self
    type(entity_t) :: item
    item%kind = entity_group_end
    call style(item)
    call push(self, item)
  end subroutine end_group

  !> Attach a data attribute (`name` = "data-force", its value) to the entity added last.
  pure subroutine attach(self, name, value)
    class(sheet_t), intent(inout) :: self
    character(*), intent(in) :: name, value
    if (self%count == 0) return
    associate (item => self%items(self%count))
      if (.not. allocated(item%data_names)) allocate (item%data_names(0), item%data_values(0))
      item%data_names = [character(len=32) :: item%data_names, name]
      item%data_values = [character(len=96) :: item%data_values, value]
    end associate
  end subroutine attach

  !> The obstacles of labels within `bounds` (x0, y0, x1, y1): every stroked or filled line
  !> of the entities drawn so far as segments (sx, sy: ends in pairs) with half widths sw,
  !> circles and arcs as polygons; texts, groups and the classes "paper", "grid", "ray" are
  !> not obstacles.
  pure subroutine obstacles(self, bounds, sx, sy, sw)
    class(sheet_t), intent(in) :: self
    real(wp), intent(in) :: bounds(4)
    real(wp), allocatable, intent(out) :: sx(:), sy(:), sw(:)
    real(wp), allocatable :: px(:), py(:)
    real(wp) :: half
    integer :: i, j, n, m
    allocate (sx(256), sy(256), sw(128))
    n = 0
    do i = 1, self%count
      associate (item => self%items(i))
        if (item%kind == entity_text .or. item%kind == entity_group .or. item%kind == entity_group_end) cycle
        if (allocated(item%class)) then
          if (item%class == "paper" .or. item%class == "grid" .or. item%class == "ray") cycle
        end if
        half = 0.5_wp * stroke_width(item)
        call outline(item, px, py)
        m = size(px)
        do j = 1, m - 1
          call add(sx, sy, sw, n, px(j), py(j), px(j + 1), py(j + 1))
        end do
        if (m == 1) call add(sx, sy, sw, n, px(1), py(1), px(1), py(1))
      end associate
    end do
    sx = sx(1:2 * n)
    sy = sy(1:2 * n)
    sw = sw(1:n)
  contains
    pure subroutine add(sx, sy, sw, n, x1, y1, x2, y2)
      real(wp), allocatable, intent(inout) :: sx(:), sy(:), sw(:)
      integer, intent(inout) :: n
      real(wp), intent(in) :: x1, y1, x2, y2
      real(wp), allocatable :: g(:)
      if (max(x1, x2) < bounds(1) .or. min(x1, x2) > bounds(3) .or. max(y1, y2) < bounds(2) .or. &
        min(y1, y2) > bounds(4)) return
      if (2 * n + 2 > size(sx)) then
        allocate (g(2 * size(sx)))
        g(1:2 * n) = sx(1:2 * n)
        call move_alloc(g, sx)
        allocate (g(2 * size(sy)))
        g(1:2 * n) = sy(1:2 * n)
        call move_alloc(g, sy)
        allocate (g(2 * size(sw)))
        g(1:n) = sw(1:n)
        call move_alloc(g, sw)
      end if
      sx(2 * n + 1:2 * n + 2) = [x1, x2]
      sy(2 * n + 1:2 * n + 2) = [y1, y2]
      n = n + 1
      sw(n) = half
    end subroutine add
  end subroutine obstacles

  !> The outline of a drawn entity as a polyline (closed shapes repeat their first point;
  !> circles as 16-gons around their stroke's outer edge for a disc).
  pure subroutine outline(item, px, py)
    type(entity_t), intent(in) :: item
    real(wp), allocatable, intent(out) :: px(:), py(:)
    integer :: i
    real(wp) :: r
    select case (item%kind)
    case (entity_line, entity_polyline)
      px = item%x
      py = item%y
    case (entity_polygon)
      px = [item%x, item%x(1)]
      py = [item%y, item%y(1)]
    case (entity_rect)
      px = [item%x(1), item%x(2), item%x(2), item%x(1), item%x(1)]
      py = [item%y(1), item%y(1), item%y(2), item%y(2), item%y(1)]
    case (entity_circle)
      r = item%radius
      allocate (px(17), py(17))
      do i = 0, 16
        px(i + 1) = item%x(1) + r * cos(i * pi / 8.0_wp)
        py(i + 1) = item%y(1) + r * sin(i * pi / 8.0_wp)
      end do
    case (entity_arc)
      call arc_points(item, px, py)
    case default
      allocate (px(0), py(0))
    end select
  end subroutine outline

  !> The stroke width an entity is drawn with, mm (a filled shape without stroke: 0.1).
  pure real(wp) function stroke_width(item)
    type(entity_t), intent(in) :: item
    stroke_width = item%width
    if (stroke_width >= 0.0_wp) return
    stroke_width = 0.0_wp
    if (allocated(item%class)) stroke_width = class_stroke_width(item%class)
    if (stroke_width == 0.0_wp) stroke_width = 0.1_wp
  end function stroke_width

  !> Stroke width of a line class, mm (0: none, or no such class).
  pure real(wp) function class_stroke_width(name)
    character(*), intent(in) :: name
    integer :: i
    class_stroke_width = 0.0_wp
    do i = 1, size(line_classes)
      if (line_classes(i)%name == name) class_stroke_width = line_classes(i)%width
    end do
  end function class_stroke_width

  !> Font size of a text class, mm (2.8 for an unknown one).
  pure real(wp) function class_font_size(name)
    character(*), intent(in) :: name
    integer :: i
    class_font_size = 2.8_wp
    do i = 1, size(text_classes)
      if (text_classes(i)%name == name) class_font_size = text_classes(i)%size
    end do
  end function class_font_size

end module kinetostat_sheet
