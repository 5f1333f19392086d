!> The one interface every mechanism implements (as fpm's subcommands do): read its deck,
!> solve every step into a step table, lay out its legacy table, print its template deck.
!> The run pipeline (kinetostat_run) and the registry (kinetostat_registry) know mechanisms
!> only through this type.
module kinetostat_mechanism
  use kinetostat_error, only: error_t, fatal_error, exit_usage
  use kinetostat_deck, only: deck_source_t
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_labels, only: in_language
  use kinetostat_table_layout, only: results_page_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_sheet, only: sheet_t
  implicit none
  private
  public :: mechanism_t

  !> A mechanism kind.
  type, abstract :: mechanism_t
    !> Title line of the legacy table, English.
    character(len=:), allocatable :: title_en
    !> Title line of the legacy table, Russian (the 1991 printout's wording where known).
    character(len=:), allocatable :: title_ru
    !> The mechanism's name on a course sheet, English and Russian ("Six-bar slotted-link
    !> mechanism of a shaper").
    character(len=:), allocatable :: name_en, name_ru
    !> The kind's commented template deck, as lines (set by the constructor, as the titles).
    character(len=:), allocatable :: template(:)
    !> Whether --format svg draws the sheet of force hodographs and diagrams (a design kind,
    !> whose results are no forces over a cycle, has none).
    logical :: force_sheet = .true.
    !> A design kind's sheet, as a file's stem ("gears", "planetary", "cam": the name a
    !> command writing every sheet of a deck gives it); "" for a kind without one.
    character(len=:), allocatable :: sheet_name
  contains
    !> The kind's titles, template deck and design sheet, set once by its constructor.
    procedure :: describe
    !> Read and validate the deck (load_deck), then derive what the kind needs from it
    !> (prepare).
    procedure :: read_deck
    !> Read and validate the kind's deck into the mechanism.
    procedure(read_deck_i), deferred :: load_deck
    !> What the kind derives from its validated deck once, before any step (a steady cycle,
    !> the tables of the reduced quantities); by default nothing.
    procedure :: prepare
    !> Compute the block's steps and fill its rows of the step table (the first block also
    !> the columns and the echo); what the run reduces over its rows goes to
    !> table%block_tally (self-check maxima, drive deviation, peaks, integrals, flags).
    procedure(solve_i), deferred :: solve
    !> The run's own summary records and warnings from the figures of the whole run
    !> (table%run_tally), once, after the last block's are merged; by default none.
    procedure :: finish_run
    !> Title line of the legacy table in a language.
    procedure :: title
    !> The mechanism's name on a course sheet in a language.
    procedure :: course_name
    !> The RESULTS block of the legacy table for rows first..last of a block (put_results).
    procedure :: write_results
    !> The RESULTS block of the legacy table: header lines and the rows as the original laid them out.
    procedure(results_i), deferred :: put_results
    !> The commented template deck.
    procedure :: write_template
    !> The topology for a drawing (links and their points, pivots, guides, gravity) after
    !> read_deck; by default not available.
    procedure :: sketch
    !> The forces of one row added to its drawing (--format svg --at K); by default none.
    procedure :: force_plan
    !> The moving links' masses, inertias and centres of mass, and gravity, named as in the
    !> kinematics columns (after read_deck); by default not available.
    procedure :: mass_model
    !> The matching analysis deck written from the run's results (--format deck); by default
    !> the kind has none.
    procedure :: analysis_deck
    !> The sheet of a design (--format svg or dxf of a kind without a sheet of forces) drawn
    !> into a sheet of the drawing model; by default the kind has none.
    procedure :: design_sheet
  end type mechanism_t

  abstract interface
    subroutine read_deck_i(self, source, error)
      import :: mechanism_t, deck_source_t, error_t
      implicit none
      class(mechanism_t), intent(inout) :: self
      !> The deck, read into memory.
      type(deck_source_t), intent(in) :: source
      !> Input error naming deck, group, variable and reason.
      type(error_t), allocatable, intent(out) :: error
    end subroutine read_deck_i

    subroutine solve_i(self, table, error)
      import :: mechanism_t, step_table_t, error_t
      implicit none
      class(mechanism_t), intent(in) :: self
      !> The results (mechanism and deck already set by the caller). A mechanism with steps
      !> computes the block table%block_range gives (all steps when the pipeline asks for no
      !> block); the first block also sets the columns, the echo and the loads.
      type(step_table_t), intent(inout) :: table
      !> Geometry error naming the step.
      type(error_t), allocatable, intent(out) :: error
    end subroutine solve_i

    pure subroutine results_i(self, table, page, out, later)
      import :: mechanism_t, step_table_t, results_page_t, text_buffer_t
      implicit none
      class(mechanism_t), intent(in) :: self
      !> Finite results: the rows of one block of the run (headings only with the first).
      type(step_table_t), intent(in) :: table
      !> The rows of the block to write, the language and whether the headings come.
      type(results_page_t), intent(in) :: page
      !> Where the lines of the RESULTS section go, and where a second section over the same
      !> rows goes (printed after the last row of the first; most layouts have none).
      type(text_buffer_t), intent(inout) :: out, later
    end subroutine results_i
  end interface

contains

  !> The kind's titles, template deck and design sheet (its constructor's one call).
  pure subroutine describe(self, template, title_en, title_ru, sheet_name, name_en, name_ru)
    class(mechanism_t), intent(inout) :: self
    !> The commented template deck, as lines.
    character(*), intent(in) :: template(:)
    !> Title line of the legacy table, English and Russian.
    character(*), intent(in) :: title_en, title_ru
    !> The design sheet's stem ("": a kind whose sheet shows the forces over a cycle).
    character(*), intent(in) :: sheet_name
    !> The mechanism's name on a course sheet, English and Russian (the subject of the
    !> sheet, in the nominative: the title line names the analysis).
    character(*), intent(in) :: name_en, name_ru
    self%template = template
    self%title_en = title_en
    self%title_ru = title_ru
    self%name_en = name_en
    self%name_ru = name_ru
    self%force_sheet = len(sheet_name) == 0
    if (len(sheet_name) > 0) self%sheet_name = sheet_name
  end subroutine describe

  !> Read and validate the deck, then what the kind derives from it.
  subroutine read_deck(self, source, error)
    class(mechanism_t), intent(inout) :: self
    !> The deck, read into memory.
    type(deck_source_t), intent(in) :: source
    !> Input error naming deck, group, variable and reason (or a later stage's error).
    type(error_t), allocatable, intent(out) :: error
    call self%load_deck(source, error)
    if (allocated(error)) return
    call self%prepare(source%path, error)
  end subroutine read_deck

  !> What the kind derives from its deck before any step: by default nothing.
  subroutine prepare(self, path, error)
    class(mechanism_t), intent(inout) :: self
    !> The deck's file, for messages.
    character(*), intent(in) :: path
    !> An error of the derivation (exit code as the kind documents).
    type(error_t), allocatable, intent(out) :: error
  end subroutine prepare

  !> The RESULTS lines of rows `first` .. `last` of a block (the headings with row 1 of the
  !> run's first block): the kind's put_results.
  pure subroutine write_results(self, table, lang, first, last, out, later)
    class(mechanism_t), intent(in) :: self
    !> Finite results: the rows of one block of the run.
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Rows of the block to write (the table writer may call it for parts of the block at once).
    integer, intent(in) :: first, last
    !> Where the RESULTS lines go, and a second section over the same rows.
    type(text_buffer_t), intent(inout) :: out, later
    call self%put_results(table, results_page_t(lang, first, last, first == 1 .and. table%first_block()), out, later)
  end subroutine write_results

  !> Title line of the legacy table in language `lang` (lang_en, lang_ru).
  pure function title(self, lang) result(text)
    class(mechanism_t), intent(in) :: self
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = in_language(self%title_en, self%title_ru, lang)
  end function title

  !> The mechanism's name on a course sheet in language `lang` (lang_en, lang_ru).
  pure function course_name(self, lang) result(text)
    class(mechanism_t), intent(in) :: self
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    character(len=:), allocatable :: text
    text = in_language(self%name_en, self%name_ru, lang)
  end function course_name

  !> The commented template deck of the kind (nothing when the constructor set none).
  pure subroutine write_template(self, out)
    class(mechanism_t), intent(in) :: self
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    if (allocated(self%template)) call out%put_lines(self%template)
  end subroutine write_template

  !> The run's summary records and warnings from its figures over the whole run: by default
  !> none (the pipeline's own summary, self-check and warnings come in any case).
  pure subroutine finish_run(self, table)
    class(mechanism_t), intent(in) :: self
    !> The results, table%run_tally holding the figures of every block.
    type(step_table_t), intent(inout) :: table
  end subroutine finish_run

  !> The topology for a drawing: by default none (`sketch%available` false).
  pure subroutine sketch(self, out)
    class(mechanism_t), intent(in) :: self
    !> The topology; names as in the kinematics columns (x_<P>, phi<i>).
    type(sketch_t), intent(out) :: out
    out%available = .false.
  end subroutine sketch

  !> The forces of row `k` of the results added to its drawing (`--format svg --at K`): pair
  !> forces at their joints, loads, weights, inertia forces and moments, the driving moment
  !> (see kinetostat_drawing). By default none: the drawing shows the links only.
  pure subroutine force_plan(self, table, k, drawing, error)
    class(mechanism_t), intent(in) :: self
    !> The results of the run (with the kinematics columns).
    type(step_table_t), intent(in) :: table
    !> Row drawn, 1..row_count.
    integer, intent(in) :: k
    !> The drawing of the row (points, links, guides) to add the forces to.
    type(drawing_t), intent(inout) :: drawing
    !> A force that cannot be placed.
    type(error_t), allocatable, intent(out) :: error
  end subroutine force_plan

  !> The mass model (moving links and gravity): by default none (`model%available` false).
  pure subroutine mass_model(self, model)
    class(mechanism_t), intent(in) :: self
    !> The moving links and gravity, after read_deck.
    type(mass_model_t), intent(out) :: model
    model%available = .false.
  end subroutine mass_model

  !> The analysis deck of a design (--format deck): by default none, a usage error.
  subroutine analysis_deck(self, table, out, error)
    class(mechanism_t), intent(in) :: self
    !> The results of the run (all rows).
    type(step_table_t), intent(in) :: table
    !> Where the deck's lines go.
    type(text_buffer_t), intent(inout) :: out
    !> The kind writes no deck, or the deck lacks what the analysis deck needs.
    type(error_t), allocatable, intent(out) :: error
    call fatal_error(error, exit_usage, "--format deck: only the design kinds (gear_geometry, "// &
      "planetary_synthesis, cam_profile) write an analysis deck; "//table%deck//" is &"//table%mechanism)
  end subroutine analysis_deck

  !> The sheet of a design, drawn into `sheet` from the run's results: by default none, a
  !> usage error.
  subroutine design_sheet(self, table, lang, at_step, sheet, error)
    class(mechanism_t), intent(in) :: self
    !> The results of the run (all rows).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> A row the sheet shows (--at K: the cam's follower drawn there); 0: the kind's choice.
    integer, intent(in) :: at_step
    !> The sheet made.
    type(sheet_t), intent(out) :: sheet
    !> The kind draws no sheet, or cannot draw this one.
    type(error_t), allocatable, intent(out) :: error
    call sheet%open(sheet%paper, lang, "", "")
    call fatal_error(error, exit_usage, "--format svg, dxf: "//table%deck//" is &"//table%mechanism// &
      ", which draws no sheet")
  end subroutine design_sheet

end module kinetostat_mechanism
