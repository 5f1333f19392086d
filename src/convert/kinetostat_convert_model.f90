!> The `&linkage` model a deck is translated into (`kinetostat convert DECK --to linkage`):
!> links, pairs, drives, loads, masses, gravity and the machine dynamics variables, with the
!> comment lines of the original deck attached to what their variables became; and the
!> writer of the model as a `&linkage` deck (one canonical layout, every number in the
!> shortest text that reads back to the same double, so that a converted deck converts to
!> itself).
module kinetostat_convert_model
  use kinetostat_kinds, only: wp
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_text, only: int_str, lower, string_t, joined
  use kinetostat_escape, only: namelist_string
  use kinetostat_dynamics, only: dynamics_none, dynamics_reduced, dynamics_steady, dynamics_given
  use kinetostat_dynamics_deck, only: dynamics_deck_t, dynamics_mode_name
  implicit none
  private
  public :: model_link_t, model_pair_t, model_drive_t, model_load_t, model_note_t, linkage_model_t
  public :: write_linkage_model, deck_number, add_note, first_variable, note_lines

  !> Values a line of a long list holds.
  integer, parameter :: per_line = 6

  !> A moving link: its number, mass (kg), moment of inertia about S (kg*m^2), centre of mass
  !> (global at the reference position, m).
  type :: model_link_t
    integer :: id = 0
    real(wp) :: m = 0.0_wp, j = 0.0_wp, s(2) = 0.0_wp
  end type model_link_t

  !> A pair: name, kind ('R' or 'P'), its links (force on the first from the second), joint
  !> (global at the reference position, m); P: the guide's direction (deg) and link.
  type :: model_pair_t
    character(len=32) :: name = ""
    character(len=1) :: kind = "R"
    integer :: links(2) = 0
    real(wp) :: at(2) = 0.0_wp
    real(wp) :: angle = 0.0_wp
    integer :: guide = 0
    !> Friction: coefficient, journal radius (m), the guide's and the block's lengths (m);
    !> a negative value is not written.
    real(wp) :: f = -1.0_wp, r = -1.0_wp, guide_length = -1.0_wp, block_length = -1.0_wp
  end type model_pair_t

  !> A drive: the pair's name; the law start + (k-1)*step or a list of values (deg or m);
  !> speed and acceleration constant or columns of step_values (0: the constants).
  type :: model_drive_t
    character(len=32) :: pair = ""
    real(wp) :: start = 0.0_wp, step = 0.0_wp
    real(wp), allocatable :: values(:)
    real(wp) :: omega = 0.0_wp, eps = 0.0_wp
    integer :: omega_column = 0, eps_column = 0
  end type model_drive_t

  !> A force (or a moment: `at`, `angle` and `follow` unused): link, value (N or N*m), its
  !> window of the first drive with the idle value, or a column of step_values.
  type :: model_load_t
    integer :: link = 0
    real(wp) :: at(2) = 0.0_wp, angle = 0.0_wp, value = 0.0_wp
    logical :: follow = .false.
    logical :: window = .false.
    real(wp) :: idle = 0.0_wp, phi_on = 0.0_wp, phi_off = 0.0_wp
    integer :: column = 0
    !> Or a table over the first drive's coordinate: pairs (position, value) as x, v.
    real(wp), allocatable :: x(:), v(:)
    !> The table's `over` link as given (0: not given).
    integer :: over = 0
  end type model_load_t

  !> A comment line of the original deck and the line of the translation it goes before
  !> ("" before `&linkage`: the deck's heading).
  type :: model_note_t
    character(len=:), allocatable :: key, text
  end type model_note_t

  !> The `&linkage` model of a deck.
  type :: linkage_model_t
    character(len=:), allocatable :: title
    integer :: frame = 0
    real(wp) :: g = 9.81_wp, gravity_angle = -90.0_wp
    integer :: n = 0
    type(model_link_t), allocatable :: links(:)
    type(model_pair_t), allocatable :: pairs(:)
    type(model_drive_t), allocatable :: drives(:)
    type(model_load_t), allocatable :: forces(:), moments(:)
    !> Per-step columns (n values a column).
    real(wp), allocatable :: step_values(:)
    type(dynamics_deck_t) :: dyn
    type(model_note_t), allocatable :: notes(:)
  end type linkage_model_t

contains

  !> The shortest decimal text of `x` that reads back to the same double: a whole number
  !> below 1e15 without a point ("12"), else fixed ("0.0025") or with an exponent ("1.5e-07").
  pure function deck_number(x) result(s)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=40) :: buf
    character(len=20) :: fmt
    integer :: d, e, ios, p
    real(wp) :: back
    character(len=:), allocatable :: digits
    logical :: negative
    if (x == 0.0_wp) then
      s = "0"
      return
    end if
    if (abs(x) < 1.0e15_wp .and. x == aint(x)) then
      write (buf, '(i0)') nint(x, kind=8)
      s = trim(buf)
      return
    end if
    do d = 1, 17
      write (fmt, '(a,i0,a,i0,a)') "(es", d + 10, ".", d - 1, "e3)"
      write (buf, fmt) x
      read (buf, *, iostat=ios) back
      if (ios == 0 .and. back == x) exit
    end do
    buf = adjustl(buf)
    negative = buf(1:1) == "-"
    if (negative) buf = buf(2:)
    p = index(buf, "E")
    read (buf(p + 1:), *) e
    digits = buf(1:1)
    if (d > 1) digits = digits//buf(3:p - 1)
    if (e >= -5 .and. e < 15) then
      if (e < 0) then
        s = "0."//repeat("0", -e - 1)//digits
      else if (len(digits) > e + 1) then
        s = digits(1:e + 1)//"."//digits(e + 2:)
      else
        s = digits//repeat("0", e + 1 - len(digits))
      end if
    else
      s = digits(1:1)
      if (len(digits) > 1) s = s//"."//digits(2:)
      s = s//"e"//int_str(e)
    end if
    if (negative) s = "-"//s
  end function deck_number

  !> Numbers "a, b, c".
  pure function number_list(x) result(s)
    real(wp), intent(in) :: x(:)
    character(len=:), allocatable :: s
    s = joined(number_part(x), ", ")
  end function number_list

  !> deck_number(x) as one part of a list.
  elemental function number_part(x) result(part)
    real(wp), intent(in) :: x
    type(string_t) :: part
    part%s = deck_number(x)
  end function number_part

  !> The variable a deck line assigns first, lower case with its index ("link(3)" of
  !> "  link(3)%m = 2"; "delta"); "" for a line that assigns none.
  pure function first_variable(line) result(name)
    character(*), intent(in) :: line
    character(len=:), allocatable :: name
    integer :: i, k
    character(len=*), parameter :: word = "abcdefghijklmnopqrstuvwxyz0123456789_"
    name = ""
    i = verify(line, " "//achar(9))
    if (i == 0) return
    k = i
    do while (k <= len(line))
      if (index(word, lower(line(k:k))) == 0) exit
      k = k + 1
    end do
    if (k == i) return
    name = lower(line(i:k - 1))
    if (k <= len(line)) then
      if (line(k:k) == "(") then
        i = index(line(k:), ")")
        if (i > 0) name = name//lower(line(k:k + i - 1))
      end if
    end if
  end function first_variable

  !> Attach a comment line to the line of the translation with `key`.
  pure subroutine add_note(model, key, text)
    type(linkage_model_t), intent(inout) :: model
    character(*), intent(in) :: key, text
    type(model_note_t) :: note
    if (.not. allocated(model%notes)) allocate (model%notes(0))
    note%key = key
    note%text = text
    model%notes = [model%notes, note]
  end subroutine add_note

  !> The comment lines attached to `key`.
  pure subroutine note_lines(model, key, out)
    type(linkage_model_t), intent(in) :: model
    character(*), intent(in) :: key
    type(text_buffer_t), intent(inout) :: out
    integer :: i
    if (.not. allocated(model%notes)) return
    do i = 1, size(model%notes)
      if (model%notes(i)%key == key) call out%put(model%notes(i)%text)
    end do
  end subroutine note_lines

  !> Write the model as a `&linkage` deck.
  subroutine write_linkage_model(model, out)
    type(linkage_model_t), intent(in) :: model
    type(text_buffer_t), intent(inout) :: out
    integer :: i
    character(len=:), allocatable :: p, line
    call note_lines(model, "", out)
    call out%put("&linkage")
    call keyed("title", "  title = "//namelist_string(model%title))
    call keyed("frame", "  frame = "//int_str(model%frame))
    call keyed("g", "  g = "//deck_number(model%g)//", gravity_angle = "//deck_number(model%gravity_angle))
    call keyed("n", "  n = "//int_str(model%n))
    do i = 1, size(model%links)
      p = "link("//int_str(i)//")%"
      associate (l => model%links(i))
        call keyed("link("//int_str(i)//")", "  "//p//"id = "//int_str(l%id)//", "//p//"m = "//deck_number(l%m)// &
          ", "//p//"j = "//deck_number(l%j)//", "//p//"s = "//number_list(l%s))
      end associate
    end do
    do i = 1, size(model%pairs)
      p = "pair("//int_str(i)//")%"
      associate (r => model%pairs(i))
        line = "  "//p//"name = "//namelist_string(trim(r%name))//", "//p//"kind = '"//r%kind//"', "//p//"links = "// &
          int_str(r%links(1))//", "//int_str(r%links(2))//", "//p//"at = "//number_list(r%at)
        if (r%kind == "P") line = line//", "//p//"angle = "//deck_number(r%angle)//", "//p//"guide = "//int_str(r%guide)
        if (r%f >= 0.0_wp) line = line//", "//p//"f = "//deck_number(r%f)
        if (r%r >= 0.0_wp) line = line//", "//p//"r = "//deck_number(r%r)
        if (r%guide_length >= 0.0_wp) line = line//", "//p//"guide_length = "//deck_number(r%guide_length)
        if (r%block_length >= 0.0_wp) line = line//", "//p//"block_length = "//deck_number(r%block_length)
        call keyed("pair("//int_str(i)//")", line)
      end associate
    end do
    do i = 1, size(model%drives)
      p = "drive("//int_str(i)//")%"
      associate (d => model%drives(i))
        line = "  "//p//"pair = "//namelist_string(trim(d%pair))
        if (.not. allocated(d%values)) line = line//", "//p//"start = "//deck_number(d%start)//", "//p//"step = "// &
          deck_number(d%step)
        if (d%omega_column > 0) then
          line = line//", "//p//"omega_column = "//int_str(d%omega_column)
        else
          line = line//", "//p//"omega = "//deck_number(d%omega)
        end if
        if (d%eps_column > 0) then
          line = line//", "//p//"eps_column = "//int_str(d%eps_column)
        else
          line = line//", "//p//"eps = "//deck_number(d%eps)
        end if
        call keyed("drive("//int_str(i)//")", line)
        if (allocated(d%values)) call put_list("  "//p//"values = ", d%values)
      end associate
    end do
    do i = 1, size(model%forces)
      p = "force("//int_str(i)//")%"
      associate (f => model%forces(i))
        line = "  "//p//"link = "//int_str(f%link)//", "//p//"at = "//number_list(f%at)//", "//p//"angle = "// &
          deck_number(f%angle)
        if (f%follow) line = line//", "//p//"follow = .true."
        call keyed("force("//int_str(i)//")", line//load_tail(p, f))
        call put_table(p, f)
      end associate
    end do
    do i = 1, size(model%moments)
      p = "moment("//int_str(i)//")%"
      associate (f => model%moments(i))
        call keyed("moment("//int_str(i)//")", "  "//p//"link = "//int_str(f%link)//load_tail(p, f))
        call put_table(p, f)
      end associate
    end do
    if (allocated(model%step_values)) then
      call note_lines(model, "step_values", out)
      call put_list("  step_values = ", model%step_values)
    end if
    if (model%dyn%mode /= dynamics_none) then
      ! only the variables the mode takes (the others are refused by the reader)
      line = "  dynamics = '"//dynamics_mode_name(model%dyn%mode)//"'"
      if (model%dyn%mode == dynamics_steady) line = line//", delta = "//deck_number(model%dyn%delta)
      if (model%dyn%mode == dynamics_given) line = line//", j_flywheel = "//deck_number(model%dyn%j_flywheel)
      line = line//", j_rotor = "//deck_number(model%dyn%j_rotor)
      if (model%dyn%mode /= dynamics_reduced) line = line//", cycle = "//deck_number(model%dyn%cycle_deg)
      call keyed("dynamics", line)
      if (model%dyn%flywheel_density /= 7800.0_wp .or. model%dyn%flywheel_width_ratio /= 0.2_wp) then
        call keyed("flywheel_density", "  flywheel_density = "//deck_number(model%dyn%flywheel_density)// &
          ", flywheel_width_ratio = "//deck_number(model%dyn%flywheel_width_ratio))
      end if
      if (allocated(model%dyn%md_phi)) then
        call note_lines(model, "md_table", out)
        call put_list("  md_table = ", reshape(transpose(reshape([model%dyn%md_phi, model%dyn%md_value], &
          [size(model%dyn%md_phi), 2])), [2 * size(model%dyn%md_phi)]))
      end if
    end if
    call out%put("/")

  contains

    !> The line of `key` after its comment lines.
    subroutine keyed(key, text)
      character(*), intent(in) :: key, text
      call note_lines(model, key, out)
      call out%put(text)
    end subroutine keyed

    !> A long list, per_line values a line.
    subroutine put_list(head, x)
      character(*), intent(in) :: head
      real(wp), intent(in) :: x(:)
      integer :: k
      do k = 1, size(x), per_line
        if (k == 1) then
          call out%put(head//number_list(x(k:min(k + per_line - 1, size(x))))//trim(merge(",", " ", &
            k + per_line <= size(x))))
        else
          call out%put(repeat(" ", len(head))//number_list(x(k:min(k + per_line - 1, size(x))))// &
            trim(merge(",", " ", k + per_line <= size(x))))
        end if
      end do
    end subroutine put_list

    !> A load's table, pairs (position, value).
    subroutine put_table(p, f)
      character(*), intent(in) :: p
      type(model_load_t), intent(in) :: f
      if (.not. allocated(f%x)) return
      call put_list("  "//p//"table = ", reshape(transpose(reshape([f%x, f%v], [size(f%x), 2])), [2 * size(f%x)]))
    end subroutine put_table

    !> A load's value: constant, windowed, a column or a table (its points on lines of their own).
    pure function load_tail(p, f) result(s)
      character(*), intent(in) :: p
      type(model_load_t), intent(in) :: f
      character(len=:), allocatable :: s
      if (allocated(f%x)) then
        s = ""
        if (f%over > 0) s = ", "//p//"over = "//int_str(f%over)
      else if (f%column > 0) then
        s = ", "//p//"column = "//int_str(f%column)
      else
        s = ", "//p//"value = "//deck_number(f%value)
        if (f%window) s = s//", "//p//"idle = "//deck_number(f%idle)//", "//p//"phi_on = "//deck_number(f%phi_on)// &
          ", "//p//"phi_off = "//deck_number(f%phi_off)
      end if
    end function load_tail
  end subroutine write_linkage_model

end module kinetostat_convert_model
