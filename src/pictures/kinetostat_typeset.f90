!> Typeset text of the drawings: the program's label text ("F21 = 2043 N", "a_CB^τ", "Phi2",
!> "MPhi3", "v_B2B3", "phi1, deg", "J_red", "dT", "N*m") turned into runs of text on the
!> baseline, lowered (subscript) or raised (superscript), as an engineer writes the symbols:
!> F₂₁, a^τ_CB, Φ₂, M_Φ3 (M_и3 on a Russian sheet), v_B2B3, φ₁, J_red (J_пр), ΔT, N·m.
!> Both writers of the drawing model use these runs: SVG as <tspan> with a shifted baseline,
!> DXF as one line of text (plain_text: "_" before a subscript that is not a number, "^"
!> before a superscript).
!>
!> What is a symbol: a token (a run of ASCII letters, digits, "_", "^" and non-ASCII
!> characters between blanks and punctuation) that is
!> - a Greek name (phi, Phi, omega, eps, delta, Delta, mu, tau, psi, pi, ...) alone or
!>   followed by an index: phi1 -> φ₁, omega_m -> ω_m, Phi2 -> Φ₂;
!> - "MPhi" with an index: MPhi3 -> M_Φ3 (ru M_и3); F or M with a point's name: MQ1 -> M_Q1,
!>   FS1 -> F_S1;
!> - "dT" -> ΔT;
!> - points named one after another, each a letter and a number: N1N2 -> N₁N₂, a1b1 -> a₁b₁;
!> - one letter with an index that starts with a digit, "_" or "^": F21 -> F₂₁, S2 -> S₂,
!>   F5c -> F_5c, a_CB^τ, v_B2B3, a^k_B2B3, J_red;
!> - a Greek letter with an index: φ1, Φ2, μv (μ takes letters: μ_v, μ_a, μ_F, μ_l).
!> Anything else (words, numbers, units, the deck's path and title, which callers pass as
!> plain text) stays as it is. An index's segments: a leading number ("21", "5c"), "_X"
!> (subscript X), "^Y" (superscript Y); two subscripts in a row are joined by a comma
!> (a_J21_3 -> a_J21,3). On a Russian sheet the course's subscripts: red -> пр, d -> д,
!> fw -> м, shake -> гл, frame -> ст, drive -> д, loss -> тр, rel -> отн, mean -> ср, max ->
!> наиб, min -> наим; the inertia moment is M_и (MPhi3 -> M_и3), the shaking force Φ_гл.
!> Units: N*m -> N·m, kg*m^2 -> kg·m², m/s^2 -> m/s² (in any text).
!>
!> The size of a typeset text (the one measure the label placement and the legibility test
!> use): a run of n characters at font size s is 0.6·s·n wide; a lowered or raised run has
!> font size 0.7·s, its baseline 0.3·s below (subscript) or 0.4·s above (superscript) the
!> text's; a run reaches from 0.8 of its font size above its baseline to 0.2 below.
module kinetostat_typeset
  use kinetostat_kinds, only: wp
  use kinetostat_labels, only: lang_ru
  use kinetostat_text, only: replace_all, is_letter, is_digit
  ! the number of UTF-8 characters of a text (continuation bytes not counted)
  use kinetostat_label_place, only: char_count => text_chars
  implicit none
  private
  public :: text_run_t, run_base, run_sub, run_sup, typeset, plain_runs, plain_text, runs_extent, &
    char_count, sub_size, sub_shift, sup_shift, unit_text

  !> Shift of a run: on the baseline.
  integer, parameter :: run_base = 0
  !> Shift of a run: lowered (subscript).
  integer, parameter :: run_sub = 1
  !> Shift of a run: raised (superscript).
  integer, parameter :: run_sup = 2
  !> Font size of a lowered or raised run, relative to the text's.
  real(wp), parameter :: sub_size = 0.7_wp
  !> Baseline of a subscript below the text's, relative to its font size.
  real(wp), parameter :: sub_shift = 0.3_wp
  !> Baseline of a superscript above the text's, relative to its font size.
  real(wp), parameter :: sup_shift = 0.4_wp

  !> A run of text with one shift.
  type :: text_run_t
    !> The characters (UTF-8).
    character(len=:), allocatable :: text
    !> run_base, run_sub or run_sup.
    integer :: shift = run_base
  end type text_run_t

  !> Greek names, longest first where one begins another, and their letters.
  character(*), parameter :: greek_names(*) = [character(len=7) :: "epsilon", "lambda", "omega", "Omega", "Delta", &
    "delta", "Sigma", "sigma", "alpha", "gamma", "theta", "Phi", "phi", "Psi", "psi", "eps", "beta", "tau", "rho", &
    "mu", "pi"]
  character(*), parameter :: greek_letters(*) = [character(len=2) :: "ε", "λ", "ω", "Ω", "Δ", "δ", "Σ", "σ", "α", &
    "γ", "θ", "Φ", "φ", "Ψ", "ψ", "ε", "β", "τ", "ρ", "μ", "π"]
  !> The course's Russian subscripts for the program's English ones.
  character(*), parameter :: sub_en(*) = [character(len=6) :: "red", "d", "fw", "shake", "frame", "drive", "loss", &
    "rel", "mean", "max", "min"]
  character(*), parameter :: sub_ru(*) = [character(len=8) :: "пр", "д", "м", "гл", "ст", "д", "тр", "отн", "ср", &
    "наиб", "наим"]

contains

  !> The typeset runs of a label text in language `lang` (see the module's description).
  pure function typeset(text, lang) result(runs)
    !> The label text, UTF-8.
    character(*), intent(in) :: text
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    type(text_run_t), allocatable :: runs(:)
    type(text_run_t), allocatable :: symbol(:)
    character(len=:), allocatable :: s
    integer :: i, j
    logical :: ok
    allocate (runs(0))
    s = unit_text(text)
    i = 1
    do while (i <= len(s))
      if (is_delimiter(s(i:i))) then
        j = i
        do while (j < len(s))
          if (.not. is_delimiter(s(j + 1:j + 1))) exit
          j = j + 1
        end do
        call push(runs, s(i:j), run_base)
      else
        j = i
        do while (j < len(s))
          if (is_delimiter(s(j + 1:j + 1))) exit
          j = j + 1
        end do
        call symbol_runs(s(i:j), lang, symbol, ok)
        if (ok) then
          call push_all(runs, symbol)
        else
          call push(runs, s(i:j), run_base)
        end if
      end if
      i = j + 1
    end do
  end function typeset

  !> One run holding `text` as it is (the deck's path and title, a student's name).
  pure function plain_runs(text) result(runs)
    !> Any text, UTF-8.
    character(*), intent(in) :: text
    type(text_run_t), allocatable :: runs(:)
    allocate (runs(1))
    runs(1)%text = text
    runs(1)%shift = run_base
  end function plain_runs

  !> The runs as one line for a writer without sub- and superscripts (DXF): a subscript
  !> after "_" unless it starts with a digit (F21, a_CB), a superscript after "^" (a_CB^τ).
  pure function plain_text(runs) result(text)
    !> The runs.
    type(text_run_t), intent(in) :: runs(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ""
    do i = 1, size(runs)
      if (len(runs(i)%text) == 0) cycle
      select case (runs(i)%shift)
      case (run_sub)
        if (index("0123456789", runs(i)%text(1:1)) == 0) text = text//"_"
      case (run_sup)
        text = text//"^"
      case default
        continue
      end select
      text = text//runs(i)%text
    end do
  end function plain_text

  !> Extent of the runs at font size 1: width (0.6 per character, 0.6·0.7 in a lowered or
  !> raised run), and how far they reach above and below the baseline.
  pure subroutine runs_extent(runs, width, above, below)
    !> The runs.
    type(text_run_t), intent(in) :: runs(:)
    !> Width, in units of the font size.
    real(wp), intent(out) :: width
    !> Reach above the baseline (positive), in units of the font size.
    real(wp), intent(out) :: above
    !> Reach below the baseline (positive), in units of the font size.
    real(wp), intent(out) :: below
    integer :: i
    width = 0.0_wp
    above = 0.8_wp
    below = 0.2_wp
    do i = 1, size(runs)
      select case (runs(i)%shift)
      case (run_sub)
        width = width + 0.6_wp * sub_size * char_count(runs(i)%text)
        above = max(above, 0.8_wp * sub_size - sub_shift)
        below = max(below, sub_shift + 0.2_wp * sub_size)
      case (run_sup)
        width = width + 0.6_wp * sub_size * char_count(runs(i)%text)
        above = max(above, sup_shift + 0.8_wp * sub_size)
        below = max(below, 0.2_wp * sub_size - sup_shift)
      case default
        width = width + 0.6_wp * char_count(runs(i)%text)
      end select
    end do
  end subroutine runs_extent

  !> `text` with the units written typographically: N*m -> N·m, kg*m^2 -> kg·m², s^2 -> s²
  !> (also the Russian symbols, Н*м -> Н·м).
  pure function unit_text(text) result(out)
    !> Any text.
    character(*), intent(in) :: text
    character(len=:), allocatable :: out
    !> What is replaced (in this order), and by what.
    character(len=*), parameter :: plain(*) = [character(len=6) :: "*m^2", "*м^2", "N*m", "Н*м", "s^2", "с^2"]
    character(len=*), parameter :: typeset(*) = [character(len=6) :: "·m²", "·м²", "N·m", "Н·м", "s²", "с²"]
    integer :: k
    out = text
    do k = 1, size(plain)
      out = replace_all(out, trim(plain(k)), trim(typeset(k)))
    end do
  end function unit_text

  !> The runs of token `t` when it is a symbol (ok); ok false otherwise.
  pure subroutine symbol_runs(t, lang, runs, ok)
    character(*), intent(in) :: t
    integer, intent(in) :: lang
    type(text_run_t), allocatable, intent(out) :: runs(:)
    logical, intent(out) :: ok
    character(len=:), allocatable :: base, rest, mark
    integer :: g, n, i, j
    allocate (runs(0))
    ok = .false.
    if (t == "dT") then
      call push(runs, "ΔT", run_base)
      ok = .true.
      return
    end if
    ! the inertia moment and an external moment: M with the force's symbol as its index
    if (len(t) > 4) then
      if (t(1:4) == "MPhi" .and. link_name(t(5:))) then
        mark = "Φ"
        if (lang == lang_ru) mark = "и"
        call push(runs, "M", run_base)
        call push(runs, mark//t(5:), run_sub)
        ok = all_index_chars(t(5:))
        return
      end if
    end if
    ! a force or moment at a named point or on a named link: FS1 -> F_S1, MQ1 -> M_Q1, GL1 -> G_L1
    if (len(t) > 2) then
      if (index("FGMQR", t(1:1)) > 0 .and. t(2:2) >= "A" .and. t(2:2) <= "Z" .and. is_digit(t(3:3))) then
        call push(runs, t(1:1), run_base)
        call push(runs, t(2:), run_sub)
        ok = all_index_chars(t(3:))
        return
      end if
    end if
    ! the shaking force and moment on a Russian sheet: the resultant of the inertia forces
    if (lang == lang_ru .and. t == "F_shake") then
      call push(runs, "Φ", run_base)
      call push(runs, "гл", run_sub)
      ok = .true.
      return
    end if
    ! a Greek name, alone or with an index
    do g = 1, size(greek_names)
      n = len_trim(greek_names(g))
      if (len(t) < n) cycle
      if (t(1:n) /= greek_names(g)(1:n)) cycle
      if (len(t) == n) then
        call push(runs, trim(greek_letters(g)), run_base)
        ok = .true.
        return
      end if
      rest = t(n + 1:)
      base = trim(greek_letters(g))
      ! a link named by a letter and a number (PhiL1)
      if (link_name(rest) .and. .not. is_digit(rest(1:1))) then
        call push(runs, base, run_base)
        call push(runs, rest, run_sub)
        ok = .true.
        return
      end if
      if (.not. (is_digit(rest(1:1)) .or. rest(1:1) == "_" .or. rest(1:1) == "^")) cycle
      call index_runs(base, rest, lang, runs, ok)
      return
    end do
    ! a Greek letter with an index (φ1, Φ2; μ with letters: μv)
    if (len(t) > 2 .and. is_greek_lead(t(1:1))) then
      base = t(1:2)
      rest = t(3:)
      if (base == "μ" .and. is_letter(rest(1:1))) then
        call push(runs, base, run_base)
        call push(runs, rest, run_sub)
        ok = all_index_chars(rest)
        return
      end if
      if (is_digit(rest(1:1)) .or. rest(1:1) == "_" .or. rest(1:1) == "^") call index_runs(base, rest, lang, runs, ok)
      return
    end if
    ! points named one after another (N1N2, B1B2, a1b1): each letter with its number lowered
    if (point_run(t)) then
      i = 1
      do while (i <= len(t))
        j = i + 1
        do while (j < len(t))
          if (.not. is_digit(t(j + 1:j + 1))) exit
          j = j + 1
        end do
        call push(runs, t(i:i), run_base)
        call push(runs, t(i + 1:j), run_sub)
        i = j + 1
      end do
      ok = .true.
      return
    end if
    ! one letter with an index
    if (len(t) >= 2 .and. is_letter(t(1:1))) then
      rest = t(2:)
      if (is_digit(rest(1:1)) .or. rest(1:1) == "_" .or. rest(1:1) == "^") call index_runs(t(1:1), rest, lang, runs, ok)
    end if
  end subroutine symbol_runs

  !> Whether `t` is two or more point names in a row, each a letter and a number (N1N2).
  pure logical function point_run(t)
    character(*), intent(in) :: t
    integer :: i, names
    point_run = .false.
    names = 0
    i = 1
    do while (i <= len(t))
      if (.not. is_letter(t(i:i))) return
      i = i + 1
      if (i > len(t)) return
      if (.not. is_digit(t(i:i))) return
      do while (i <= len(t))
        if (.not. is_digit(t(i:i))) exit
        i = i + 1
      end do
      names = names + 1
    end do
    point_run = names >= 2
  end function point_run

  !> Runs of `base` followed by the index `rest`: a leading number, then "_X" and "^Y"
  !> segments; ok false when the index is not one.
  pure subroutine index_runs(base, rest, lang, runs, ok)
    character(*), intent(in) :: base, rest
    integer, intent(in) :: lang
    type(text_run_t), allocatable, intent(inout) :: runs(:)
    logical, intent(out) :: ok
    integer :: i, j, last_shift
    character(len=:), allocatable :: part
    ok = .false.
    call push(runs, base, run_base)
    last_shift = run_base
    i = 1
    do while (i <= len(rest))
      if (rest(i:i) == "_" .or. rest(i:i) == "^") then
        j = i + 1
      else
        j = i
      end if
      ! the segment: up to the next "_" or "^"
      part = ""
      do while (j <= len(rest))
        if (rest(j:j) == "_" .or. rest(j:j) == "^") exit
        part = part//rest(j:j)
        j = j + 1
      end do
      if (len(part) == 0 .or. .not. all_index_chars(part)) return
      ! a leading number with a word after it (phi3rel): the word in the course's words
      if (rest(i:i) /= "_" .and. rest(i:i) /= "^" .and. lang == lang_ru) part = number_word(part)
      if (rest(i:i) == "^") then
        call push(runs, greek_index(part), run_sup)
        last_shift = run_sup
      else
        if (rest(i:i) == "_" .and. lang == lang_ru) part = course_subscript(part)
        if (rest(i:i) == "_") part = greek_index(part)
        ! two subscripts in a row: one index, its parts joined by a comma
        if (last_shift == run_sub) then
          call push(runs, ","//part, run_sub)
        else
          call push(runs, part, run_sub)
        end if
        last_shift = run_sub
      end if
      i = j
    end do
    ok = .true.
  end subroutine index_runs

  !> An index segment with a Greek name written as its letter ("Phi3" -> "Φ3", "tau" -> "τ").
  pure function greek_index(part) result(out)
    character(*), intent(in) :: part
    character(len=:), allocatable :: out
    integer :: g, n
    out = part
    do g = 1, size(greek_names)
      n = len_trim(greek_names(g))
      if (len(part) < n) cycle
      if (part(1:n) /= greek_names(g)(1:n)) cycle
      if (len(part) > n) then
        if (.not. is_digit(part(n + 1:n + 1))) cycle
      end if
      out = trim(greek_letters(g))//part(n + 1:)
      return
    end do
  end function greek_index

  !> The course's Russian subscript for an English one (red -> пр), or the same.
  pure function course_subscript(part) result(out)
    character(*), intent(in) :: part
    character(len=:), allocatable :: out
    integer :: i
    i = findloc(sub_en, part, dim=1)
    if (i > 0) then
      out = trim(sub_ru(i))
    else
      out = part
    end if
  end function course_subscript

  !> Whether `rest` names a link or point as an index: a number ("3", "21"), or a capital
  !> letter and a number ("L1").
  pure logical function link_name(rest)
    character(*), intent(in) :: rest
    integer :: i
    link_name = .false.
    if (len(rest) == 0) return
    i = 1
    if (rest(1:1) >= "A" .and. rest(1:1) <= "Z") i = 2
    if (i > len(rest)) return
    link_name = verify(rest(i:), "0123456789") == 0
  end function link_name

  !> A number with a word after it ("3rel") with the word in the course's words ("3отн").
  pure function number_word(part) result(out)
    character(*), intent(in) :: part
    character(len=:), allocatable :: out
    integer :: i
    out = part
    do i = 1, len(part)
      if (.not. is_digit(part(i:i))) exit
    end do
    if (i > 1 .and. i <= len(part)) out = part(:i - 1)//course_subscript(part(i:))
  end function number_word

  !> Whether every character of an index segment is one (ASCII letters, digits, non-ASCII).
  pure logical function all_index_chars(part)
    character(*), intent(in) :: part
    integer :: i
    all_index_chars = len(part) > 0
    do i = 1, len(part)
      if (.not. (is_letter(part(i:i)) .or. is_digit(part(i:i)) .or. iachar(part(i:i)) >= 128)) then
        all_index_chars = .false.
        return
      end if
    end do
  end function all_index_chars

  !> Whether byte `c` ends a token: ASCII that is not a letter, digit, "_" or "^".
  pure logical function is_delimiter(c)
    character, intent(in) :: c
    is_delimiter = iachar(c) < 128 .and. .not. (is_letter(c) .or. is_digit(c) .or. c == "_" .or. c == "^")
  end function is_delimiter

  !> Whether byte `c` leads a two-byte Greek letter (U+0391..U+03C9: 0xCE, 0xCF).
  pure logical function is_greek_lead(c)
    character, intent(in) :: c
    is_greek_lead = iachar(c) == 206 .or. iachar(c) == 207
  end function is_greek_lead

  !> Append a run (joined to the last one when it has the same shift).
  pure subroutine push(runs, text, shift)
    type(text_run_t), allocatable, intent(inout) :: runs(:)
    character(*), intent(in) :: text
    integer, intent(in) :: shift
    type(text_run_t), allocatable :: grown(:)
    integer :: i, n
    n = size(runs)
    if (n > 0) then
      if (runs(n)%shift == shift) then
        runs(n)%text = runs(n)%text//text
        return
      end if
    end if
    ! element by element (gfortran and deferred-length components in array constructors),
    ! each run's text moved, not copied
    allocate (grown(n + 1))
    do i = 1, n
      call move_alloc(runs(i)%text, grown(i)%text)
      grown(i)%shift = runs(i)%shift
    end do
    grown(n + 1)%text = text
    grown(n + 1)%shift = shift
    call move_alloc(grown, runs)
  end subroutine push

  !> Append every run of `more`.
  pure subroutine push_all(runs, more)
    type(text_run_t), allocatable, intent(inout) :: runs(:)
    type(text_run_t), intent(in) :: more(:)
    integer :: i
    do i = 1, size(more)
      call push(runs, more(i)%text, more(i)%shift)
    end do
  end subroutine push_all

end module kinetostat_typeset
