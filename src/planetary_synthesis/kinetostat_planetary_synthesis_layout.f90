!> Tooth numbers of a planetary train as a mechanism of the run pipeline: deck -> the search
!> -> one row (z1, z2, z3, k, u_actual and how each condition is met), the legacy block with
!> every condition in words, and the analysis deck (--format deck: a `&gears` planetary stage).
module kinetostat_planetary_synthesis_layout
  use kinetostat_kinds, only: wp
  use kinetostat_deck, only: deck_source_t
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str
  use kinetostat_step_table, only: step_table_t, column_t, column, col_count, col_ratio
  use kinetostat_table_layout, only: results_page_t, heading_of, column_value
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_table_writer, only: put_heading, value_line
  use kinetostat_format, only: full_number, int_field, pad_right, short_number
  use kinetostat_labels, only: lang_ru
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_sheet, only: sheet_t
  use kinetostat_planetary_sheet, only: draw_planetary_sheet
  use kinetostat_planetary_synthesis, only: planetary_train_t, planetary_search, train_conditions
  use kinetostat_planetary_synthesis_deck, only: planetary_synthesis_deck_t, read_planetary_synthesis_deck, &
    planetary_synthesis_template
  implicit none
  private
  public :: planetary_synthesis_mechanism_t, new_planetary_synthesis, planetary_columns

  !> Title lines of the legacy table (English, Russian).
  character(*), parameter :: title_en = "KINETOSTAT  PLANETARY_SYNTHESIS  TOOTH NUMBERS OF A SINGLE-ROW PLANETARY TRAIN", &
    title_ru = "KINETOSTAT  PLANETARY_SYNTHESIS  ПОДБОР ЧИСЕЛ ЗУБЬЕВ ОДНОРЯДНОГО"// &
      " ПЛАНЕТАРНОГО МЕХАНИЗМА"

  !> Tooth numbers of a single-row planetary train.
  type, extends(mechanism_t) :: planetary_synthesis_mechanism_t
    !> The validated deck: the ratio wanted and the limits of the train.
    type(planetary_synthesis_deck_t) :: deck
  contains
    procedure :: load_deck, solve, put_results, analysis_deck, design_sheet
  end type planetary_synthesis_mechanism_t

contains

  !> A new mechanism of this kind (the registry's constructor).
  subroutine new_planetary_synthesis(mech)
    !> The mechanism.
    class(mechanism_t), allocatable, intent(out) :: mech
    allocate (planetary_synthesis_mechanism_t :: mech)
    call mech%describe(planetary_synthesis_template, title_en, title_ru, "planetary", &
      "Single-row planetary train", &
      "Однорядный планетарный механизм")
  end subroutine new_planetary_synthesis

  subroutine load_deck(self, source, error)
    class(planetary_synthesis_mechanism_t), intent(inout) :: self
    type(deck_source_t), intent(in) :: source
    type(error_t), allocatable, intent(out) :: error
    call read_planetary_synthesis_deck(source, self%deck, error)
  end subroutine load_deck

  !> The search into one row, with the INPUT DATA echo.
  subroutine solve(self, table, error)
    class(planetary_synthesis_mechanism_t), intent(in) :: self
    type(step_table_t), intent(inout) :: table
    type(error_t), allocatable, intent(out) :: error
    type(planetary_train_t) :: t
    call planetary_search(self%deck%spec, t, error)
    if (allocated(error)) then
      error%message = table%deck//": &"//table%mechanism//": "//error%message
      return
    end if
    call table%declare_record(planetary_columns(), "train", "u_actual")
    table%has_selfcheck = .false.
    table%rows(:, 1) = [real(t%z1, wp), real(t%z2, wp), real(t%z3, wp), real(self%deck%spec%k, wp), t%u_actual, &
      t%u_deviation, t%assembly_number, t%neighbour_margin]
    call table%echo_text("SCHEME", "single_row")
    call table%echo_real("U", self%deck%spec%u, "")
    call table%echo_int("K", self%deck%spec%k, "satellites")
    call table%echo_real("U_TOLERANCE", self%deck%spec%u_tolerance, "")
    call table%echo_int("Z_MIN", self%deck%spec%z_min, "")
    call table%echo_int("Z_RING_MIN", self%deck%spec%z_ring_min, "")
    if (self%deck%has_m) call table%echo_real("M", self%deck%m, "mm")
    if (self%deck%has_m1) call table%echo_real("M1", self%deck%m1, "N*m")
  end subroutine solve

  !> The columns of the one row (docs/planetary-synthesis.md): the tooth numbers and the
  !> satellites (headed counts in RESULTS), the ratio and its deviation (headed values),
  !> the assembly number and the neighbours' margin (in the conditions' words).
  pure function planetary_columns() result(cols)
    type(column_t), allocatable :: cols(:)
    cols = [column("z1", "", col_count, heading="Z1"), column("z2", "", col_count, heading="Z2"), &
            column("z3", "", col_count, heading="Z3"), column("k", "", col_count, heading="K"), &
            column("u_actual", "", col_ratio, heading="U_ACTUAL"), &
            column("u_deviation", "", col_ratio, heading="U_DEVIATION"), column("assembly_number", "", col_ratio), &
            column("neighbour_margin", "", col_ratio)]
  end function planetary_columns

  !> RESULTS: the tooth numbers and the ratio, then every condition with its numbers.
  pure subroutine put_results(self, table, page, out, later)
    class(planetary_synthesis_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(results_page_t), intent(in) :: page
    type(text_buffer_t), intent(inout) :: out, later
    !> The conditions' names in English (column 1) and Russian (column 2).
    character(*), parameter :: names(5, 2) = reshape([character(len=20) :: &
      "COAXIALITY", "ASSEMBLY", "NEIGHBOURS", "LEAST TEETH", "RATIO", &
      "СООСНОСТЬ", "СБОРКА", "СОСЕДСТВО", "ЗУБЬЯ", "ОТНОШЕНИЕ"], [5, 2])
    type(planetary_train_t) :: t
    integer :: z1, z2, z3, k, l, c
    character(len=:), allocatable :: met, whole
    integer :: lang
    if (page%first > 1 .or. page%last < 1) return
    lang = page%lang
    z1 = nint(column_value(table, "z1", 1))
    z2 = nint(column_value(table, "z2", 1))
    z3 = nint(column_value(table, "z3", 1))
    k = nint(column_value(table, "k", 1))
    ! the headed columns: counts as whole numbers, ratios as values
    do c = 1, size(table%columns)
      if (len(table%columns(c)%heading) == 0) cycle
      if (table%columns(c)%kind == col_count) then
        call out%put(count_line(heading_of(table%columns(c), lang), nint(table%rows(c, 1))))
      else
        call out%put(value_line(heading_of(table%columns(c), lang), table%rows(c, 1), ""))
      end if
    end do
    t = train_conditions(self%deck%spec, z1, z2, z3)
    l = merge(2, 1, lang == lang_ru)
    if (l == 2) then
      call put_heading(out, "УСЛОВИЯ ПОДБОРА ЧИСЕЛ ЗУБЬЕВ")
      met = "ВЫПОЛНЕНО"
      whole = " - ЦЕЛОЕ"
    else
      call put_heading(out, "CONDITIONS OF THE TRAIN")
      met = "MET"
      whole = ", A WHOLE NUMBER"
    end if
    call out%put(condition(trim(names(1, l)), "Z3 = Z1 + 2*Z2: "//int_str(z3)//" = "//int_str(z1)//" + "// &
      int_str(2 * z2), t%met(1), met))
    call out%put(condition(trim(names(2, l)), "(Z1 + Z3)/K = "//int_str(z1 + z3)//"/"//int_str(k)//" = "// &
      short_number(t%assembly_number)//whole, t%met(2), met))
    call out%put(condition(trim(names(3, l)), neighbour_text("sin"), t%met(3), met))
    call out%put(condition(trim(names(4, l)), "Z1 = "//int_str(z1)//", Z2 = "//int_str(z2)//" >= "// &
      int_str(self%deck%spec%z_min)//"; Z3 = "//int_str(z3)//" >= "//int_str(self%deck%spec%z_ring_min), &
      t%met(4) .and. t%met(5), met))
    call out%put(condition(trim(names(5, l)), ratio_text(), t%met(6), met))
  contains
    pure function count_line(name, n) result(line)
      character(*), intent(in) :: name
      integer, intent(in) :: n
      character(len=:), allocatable :: line
      line = "   "//pad_right(name, 16)//"="//int_field(real(n, wp), 18)
    end function count_line
    pure function neighbour_text(sine) result(text)
      character(*), intent(in) :: sine
      character(len=:), allocatable :: text
      if (k == 1) then
        text = "K = 1"
      else
        text = "(Z1 + Z2)*"//sine//"(180/K) = "//short_number(t%neighbour_margin + real(z2 + 2, wp))//" > Z2 + 2 = "// &
          int_str(z2 + 2)
      end if
    end function neighbour_text
    pure function ratio_text() result(text)
      character(len=:), allocatable :: text
      text = "|1 + Z3/Z1 - U| = "//short_number(abs(t%u_actual - self%deck%spec%u))//" <= U_TOLERANCE*U = "// &
        short_number(self%deck%spec%u_tolerance * self%deck%spec%u)
    end function ratio_text
  end subroutine put_results

  !> "   NAME           formula   MET" (NOT MET never occurs in an answer, but is said).
  pure function condition(name, formula, ok, met) result(line)
    character(*), intent(in) :: name, formula
    logical, intent(in) :: ok
    character(*), intent(in) :: met
    character(len=:), allocatable :: line
    line = "   "//pad_right(name, 16)//formula
    if (ok) then
      line = line//"   "//met
    else
      line = line//"   !!"
    end if
  end function condition

  !> The matching analysis deck: a `&gears` planetary stage of the train, driven by m1 on
  !> the sun, with the module m.
  subroutine analysis_deck(self, table, out, error)
    class(planetary_synthesis_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    if (.not. (self%deck%has_m .and. self%deck%has_m1)) then
      call fatal_error(error, exit_input, table%deck//": &planetary_synthesis: "// &
        trim(merge("m1", "m ", self%deck%has_m))//": missing: --format deck needs the module m (mm) and the "// &
        "torque on the sun m1 (N*m) of the &gears deck it writes")
      return
    end if
    call out%put("! kinetostat deck: the forces in the planetary train chosen by a &planetary_synthesis deck")
    call out%put("! (kinetostat --format deck): u = "//short_number(self%deck%spec%u)//" asked, u_1H = "// &
      short_number(column_value(table, "u_actual", 1))//".")
    call out%put("&gears")
    call out%put("  stage = 'planetary'")
    call out%put("  m1    = "//full_number(self%deck%m1)//"   ! N*m, torque on the sun from its shaft")
    call out%put("  z1    = "//int_str(nint(column_value(table, "z1", 1)))//"   ! sun")
    call out%put("  z2    = "//int_str(nint(column_value(table, "z2", 1)))//"   ! planet")
    call out%put("  z3    = "//int_str(nint(column_value(table, "z3", 1)))//"   ! ring (fixed)")
    call out%put("  k     = "//int_str(nint(column_value(table, "k", 1)))//"   ! planets")
    call out%put("  m     = "//full_number(self%deck%m)//"   ! mm, module")
    call out%put("/")
  end subroutine analysis_deck

  !> The sheet of the train (--format svg, dxf): its kinematic scheme, the picture of linear
  !> speeds, the view along the axis, the conditions (kinetostat_planetary_sheet).
  subroutine design_sheet(self, table, lang, at_step, sheet, error)
    class(planetary_synthesis_mechanism_t), intent(in) :: self
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    integer, intent(in) :: at_step
    type(sheet_t), intent(out) :: sheet
    type(error_t), allocatable, intent(out) :: error
    call draw_planetary_sheet(self%deck%spec, nint(column_value(table, "z1", 1)), nint(column_value(table, "z2", 1)), &
      nint(column_value(table, "z3", 1)), nint(column_value(table, "k", 1)), &
      merge(self%deck%m, 0.0_wp, self%deck%has_m), table, lang, sheet)
  end subroutine design_sheet

end module kinetostat_planetary_synthesis_layout
