!> Unit tests of the defences against hostile or extreme input: the deck's syntax pre-check,
!> the deck size limit, text made printable for messages and JSON, summary means of values
!> near the largest real, and self-check scales that cannot vanish.
module test_hostile
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, exit_input
  use kinetostat_text, only: printable, utf8_length, char_count, is_name
  use kinetostat_escape, only: xml_escape, csv_field, dxf_text, table_text
  use kinetostat_deck_encoding, only: deck_as_utf8, utf8_problem
  use kinetostat_deck, only: deck_source_t, deck_source_from_text, check_namelist_syntax, longest_quoted, &
    load_deck, set_max_deck_size, default_max_deck_size
  use kinetostat_json_writer, only: json_string
  use kinetostat_step_table, only: step_table_t, col_input_angle, col_force
  use kinetostat_summary, only: tally_rows, column_stats, column_stats_t
  use kinetostat_selfcheck, only: link_balance_t, balance_add_force, equilibrium_residual, power_mismatch, &
    load_moment_scale
  use test_harness, only: test_counts_t, check_true, check_close
  implicit none
  private
  public :: run_hostile_tests

contains

  subroutine run_hostile_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_printable(t)
    call test_escapers(t)
    call test_encoding(t)
    call test_syntax(t)
    call test_size_limit(t)
    call test_huge_means(t)
    call test_selfcheck_scales(t)
  end subroutine run_hostile_tests

  !> Messages and JSON: control characters and bytes that are not UTF-8 escaped, UTF-8 kept.
  subroutine test_printable(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: cyrillic = char(208)//char(180)//char(208)//char(176)  ! "да"
    call check_true(t, "printable newline and 0xFF", printable("a"//achar(10)//"b"//char(255)) == "a\nb\xFF", &
                    "expected a\nb\xFF, got "//printable("a"//achar(10)//"b"//char(255)))
    call check_true(t, "printable keeps UTF-8", printable("x "//cyrillic) == "x "//cyrillic, "UTF-8 changed")
    call check_true(t, "printable escapes a cut UTF-8 sequence", printable("x"//char(208)) == "x\xD0", &
                    "got "//printable("x"//char(208)))
    call check_true(t, "utf8_length of a CP1251 byte", utf8_length(char(224)//"a", 1) == 0, "0 expected")
    call check_true(t, "json_string escapes a Latin-1 byte", json_string("caf"//char(233)) == '"caf\u00E9"', &
                    "got "//json_string("caf"//char(233)))
    call check_true(t, "json_string keeps UTF-8", json_string(cyrillic) == '"'//cyrillic//'"', "UTF-8 changed")
  end subroutine test_printable

  !> Each output format's escaper on hostile text: quotes, markup, separators, control
  !> characters, bytes that are not UTF-8, non-ASCII letters.
  subroutine test_escapers(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: lf = achar(10), cyr = char(208)//char(180)  ! "д", U+0434
    character(len=*), parameter :: hostile = 'a"b<c>&]]>'//lf//"x"//achar(1)//char(255)//"'"
    call expect(t, "xml_escape hostile", xml_escape(hostile), "a&quot;b&lt;c&gt;&amp;]]&gt;\nx\x01\xFF&apos;")
    call expect(t, "xml_escape keeps UTF-8", xml_escape("x "//cyr), "x "//cyr)
    call expect(t, "xml_escape U+FFFE", xml_escape("a"//char(239)//char(191)//char(190)), "a\xEF\xBF\xBE")
    call expect(t, "csv_field plain", csv_field("l_ab"), "l_ab")
    call expect(t, "csv_field quotes", csv_field('a,"b" c'), '"a,""b"" c"')
    call expect(t, "csv_field one line", csv_field("a"//lf//"b"//achar(13)//char(255)), "a\nb\r\xFF")
    call expect(t, "dxf_text Cyrillic", dxf_text("A"//cyr), "A\U+0434")
    call expect(t, "dxf_text 4-byte", dxf_text(char(240)//char(159)//char(152)//char(128)), "\U+D83D\U+DE00")
    call expect(t, "dxf_text one line", dxf_text("x"//lf//"  0"//lf//"EOF"), "x\n  0\nEOF")
    call expect(t, "dxf_text caret and percent", dxf_text("^J 50%%d"), "^ J 50%%%%%%d")
    call expect(t, "dxf_text plain", dxf_text("F21 = 10 N"), "F21 = 10 N")
    call expect(t, "table_text one line", table_text("a"//lf//"INJECTED"//achar(9)), "a\nINJECTED\t")
    call check_true(t, "char_count Cyrillic", char_count(repeat(cyr, 45)) == 45, "45 expected")
    call check_true(t, "char_count bad byte", char_count("a"//char(255)//"b") == 3, "3 expected")
    call check_true(t, "utf8_length overlong", utf8_length(char(192)//char(128), 1) == 0 .and. &
      utf8_length(char(224)//char(128)//char(128), 1) == 0, "an overlong form accepted")
    call check_true(t, "utf8_length surrogate", utf8_length(char(237)//char(160)//char(128), 1) == 0, &
      "a surrogate accepted")
    call check_true(t, "is_name", is_name("A1_b") .and. is_name(repeat(cyr, 5)) .and. .not. is_name("1A") .and. &
      .not. is_name("a-b") .and. .not. is_name("") .and. .not. is_name("a"//char(255)), "wrong verdict")
  contains
    subroutine expect(t, name, computed, expected)
      type(test_counts_t), intent(inout) :: t
      character(*), intent(in) :: name, computed, expected
      call check_true(t, name, computed == expected, "expected '"//printable(expected)//"', got '"// &
        printable(computed)//"'")
    end subroutine expect
  end subroutine test_escapers

  !> Decks as UTF-8: kept when they are, CP1251 Cyrillic decoded, anything else refused with
  !> the line and the byte.
  subroutine test_encoding(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: lf = achar(10)
    character(len=:), allocatable :: text, problem
    ! "Шарнир Ёё" in CP1251 and in UTF-8
    character(len=*), parameter :: cp = char(216)//char(224)//char(240)//char(237)//char(232)//char(240)//" "// &
      char(168)//char(184)
    character(len=*), parameter :: u8 = char(208)//char(168)//char(208)//char(176)//char(209)//char(128)// &
      char(208)//char(189)//char(208)//char(184)//char(209)//char(128)//" "//char(208)//char(129)//char(209)//char(145)
    text = "&g title = '"//u8//"' /"
    call deck_as_utf8(text, problem)
    call check_true(t, "utf-8 deck kept", len(problem) == 0 .and. text == "&g title = '"//u8//"' /", problem)
    text = "! x"//lf//"&g title = '"//cp//"' /"
    call deck_as_utf8(text, problem)
    call check_true(t, "cp1251 deck decoded", len(problem) == 0 .and. text == "! x"//lf//"&g title = '"//u8//"' /", &
      printable(problem//" "//text))
    text = "&g"//lf//" title = '"//cp//"'"//lf//" ! 30"//char(176)//lf//"/"
    call deck_as_utf8(text, problem)
    call check_true(t, "cp1251 degree refused", problem == "3: byte \xB0 is neither UTF-8 nor a Cyrillic letter of "// &
      "CP1251 (save the deck as UTF-8)", problem)
    text = "&g"//lf//" title = '"//u8//"'"//lf//" ! "//cp//lf//"/"
    call deck_as_utf8(text, problem)
    call check_true(t, "mixed encodings refused", index(problem, "3: byte \xD8 is not UTF-8, but line 2 is UTF-8") == 1, &
      problem)
    call check_true(t, "utf8_problem", utf8_problem("0.1"//char(255)) == "byte \xFF is not UTF-8" .and. &
      len(utf8_problem(u8)) == 0, utf8_problem("0.1"//char(255)))
  end subroutine test_encoding

  !> The pre-check refuses what crashed gfortran's READ and names line and variable; it
  !> passes valid decks (subscripts, complex-like values, quotes with doubled quotes).
  subroutine test_syntax(t)
    type(test_counts_t), intent(inout) :: t
    character(len=*), parameter :: lf = achar(10)
    call expect_syntax(t, "syntax unclosed paren after a type name", "&assur dyad(", &
                       "d.nml:1: &assur: dyad(: unclosed '('")
    call expect_syntax(t, "syntax unclosed paren in a value", "&assur"//lf//"  title = dyad("//lf//"/", &
                       "d.nml:2: &assur: dyad(: unclosed '('")
    call expect_syntax(t, "syntax stray close", "&cam"//lf//"  l = 1)"//lf//"/", "d.nml:2: &cam: l: ')' without '('")
    call expect_syntax(t, "syntax bare equals", "&cam"//lf//" = 1"//lf//"/", "d.nml:2: &cam: (no variable yet): '='")
    call expect_syntax(t, "syntax unclosed quote", "&assur"//lf//"  title = 'abc"//lf//"/", &
                       "d.nml:2: &assur: title: unclosed quote '")
    call expect_syntax(t, "syntax valid deck", "! c (x"//lf//"&assur title = 'it''s (', dyad(1)%at2 = 0.1, 0"// &
                       lf//"  f5c(1:2) = 2*0, x = (1.0, 2.0) ! (open"//lf//"/ ! dyad("//lf//lf//"  ! end", "")
    ! after the closing '/': comments only; a '/' between two numbers is a fraction
    call expect_syntax(t, "syntax text after the group", "&cam"//lf//"  l = 1"//lf//"/"//lf//"  l_ab = 5", &
                       "d.nml:4: &x: l_ab = 5: text after the group's closing '/'")
    call expect_syntax(t, "syntax text after the slash", "&cam l = 1 / f = 2 ! c", &
                       "d.nml:1: &x: f = 2 ! c: text after the group's closing '/'")
    call expect_syntax(t, "syntax fraction", "&cam"//lf//"  delta = 1/25, j_rotor = 0.6"//lf//"/", &
                       "d.nml:2: &x: delta = 1/25: a fraction? write 0.04")
    call expect_syntax(t, "syntax fraction 1/16", "&cam j_flywheel = 1/16", &
                       "d.nml:1: &x: j_flywheel = 1/16: a fraction? write 0.0625")
    call expect_syntax(t, "syntax fraction whole", "&cam n = 12/4", "d.nml:1: &x: n = 12/4: a fraction? write 3")
    call expect_syntax(t, "syntax fraction by zero", "&cam a = 1./0", "d.nml:1: &x: a = 1./0: a fraction? a namelist value")
    call expect_syntax(t, "syntax slash after a number", "&cam n = 12/"//lf//"! done", "")
    ! a quoted text but the title has at most text_chars characters (counted, not bytes)
    call expect_syntax(t, "syntax long text", "&cam follower = '"//repeat("x", 33)//"' /", &
                       "d.nml:1: &x: follower: a text of 33 characters")
    call expect_syntax(t, "syntax long Cyrillic text fits", "&cam follower = '"//repeat("Ш", 32)//"' /", "")
    call expect_syntax(t, "syntax long title", "&cam title = '"//repeat("x", 300)//"' /", "")
    block
      type(deck_source_t) :: source
      call deck_source_from_text("d.nml", "&assur title = '"//repeat("x", 1000)//"', t2 = 'a''b'"//lf//"/", source)
      call check_true(t, "longest quoted text", longest_quoted(source) == 1000, "1000 expected")
    end block
  end subroutine test_syntax

  !> The pre-check of `text` gives an error starting with `expected` ("" : no error).
  subroutine expect_syntax(t, name, text, expected)
    type(test_counts_t), intent(inout) :: t
    character(*), intent(in) :: name, text, expected
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    call deck_source_from_text("d.nml", text, source)
    call check_namelist_syntax(source, "x", error)
    if (len(expected) == 0) then
      if (allocated(error)) then
        call check_true(t, name, .false., "unexpected error: "//error%message)
      else
        call check_true(t, name, .true., "")
      end if
      return
    end if
    if (.not. allocated(error)) then
      call check_true(t, name, .false., "no error, expected "//expected)
      return
    end if
    ! the group name comes from the caller's context in the mechanisms; here "x"
    call check_true(t, name, index(error%message, replace_group(expected)) == 1 .and. error%code == exit_input, &
                    "expected '"//replace_group(expected)//"...', got '"//error%message//"'")
  end subroutine expect_syntax

  !> `text` with its "&name:" made "&x:" (the group the test passes).
  function replace_group(text) result(out)
    character(*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: a, c
    a = index(text, "&")
    c = index(text(a:), ":")
    out = text(1:a)//"x"//text(a + c - 1:)
  end function replace_group

  !> A device without end (/dev/zero) stops at the limit with an input error.
  subroutine test_size_limit(t)
    type(test_counts_t), intent(inout) :: t
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    call set_max_deck_size(100000_int64)
    call load_deck("/dev/zero", source, error)
    call set_max_deck_size(default_max_deck_size)
    call check_true(t, "deck limit stops /dev/zero", allocated(error), "no error")
    if (allocated(error)) call check_true(t, "deck limit message", &
      error%message == "/dev/zero: the deck is longer than the limit of 100000 bytes (endless input? raise the "// &
      "limit with --max-deck-size)", error%message)
  end subroutine test_size_limit

  !> Means of values near the largest real are finite and right (the sums kept scaled).
  subroutine test_huge_means(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    type(column_stats_t) :: s
    real(wp), parameter :: big = 1.7e308_wp
    table%mechanism = "demo"
    table%deck = "d.nml"
    call table%add_column("phi1", "deg", col_input_angle)
    call table%add_column("F", "N", col_force)
    table%input_column = 1
    call table%allocate_rows(3)
    table%rows(:, 1) = [0.0_wp, big]
    table%rows(:, 2) = [30.0_wp, big]
    table%rows(:, 3) = [90.0_wp, 0.5_wp * big]
    call tally_rows(table)
    s = column_stats(table, 2)
    ! trapezoid mean: (30*(big + big)/2 + 60*(big + big/2)/2) / 90 = big * (30 + 45) / 90
    call check_close(t, "huge trapezoid mean", big * 75.0_wp / 90.0_wp, s%mean, 1.0e-15_wp, 0.0_wp)
    table%input_column = 0
    s = column_stats(table, 2)
    call check_close(t, "huge row mean", big * 2.5_wp / 3.0_wp, s%mean, 1.0e-15_wp, 0.0_wp)
  end subroutine test_huge_means

  !> A link whose forces all pass through its origin, with a roundoff-level force, and a
  !> driving moment at roundoff where no load does work: both judged against the loads.
  subroutine test_selfcheck_scales(t)
    type(test_counts_t), intent(inout) :: t
    type(link_balance_t) :: links(2)
    real(wp) :: residual, mismatch
    ! link 1: a slider, 100 N across its guide balanced by the guide, both at its origin
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [0.0_wp, 100.0_wp])
    call balance_add_force(links(1), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [0.0_wp, -100.0_wp])
    ! link 2: a massless rod 0.2 m long carrying roundoff only
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp], [3.0e-15_wp, 1.0e-15_wp])
    call balance_add_force(links(2), [0.0_wp, 0.0_wp], [0.2_wp, 0.0_wp], [-3.0e-15_wp, 0.0_wp])
    residual = equilibrium_residual(links)
    call check_true(t, "residual of roundoff against the loads", residual <= 1.0e-9_wp, &
                    "residual above 1e-9 (a moment floor of 0 would give ~1)")
    call check_close(t, "load moment scale", 40.0_wp, load_moment_scale(links, 0.05_wp), 1.0e-15_wp, 0.0_wp)
    mismatch = power_mismatch(5.0e-16_wp, 0.0_wp, 0.0_wp, load_moment_scale(links, 0.05_wp))
    call check_true(t, "roundoff M1 with no power against the loads", mismatch <= 1.0e-9_wp, &
                    "mismatch above 1e-9")
    mismatch = power_mismatch(5.0e-16_wp, 0.0_wp, 0.0_wp)
    call check_true(t, "roundoff M1 against itself fails (the old scale)", mismatch > 0.5_wp, "mismatch <= 0.5")
    mismatch = power_mismatch(12.0_wp, 4.0_wp, 4.0_wp, load_moment_scale(links, 0.05_wp))
    call check_true(t, "a wrong M1 still fails", mismatch > 1.0e-6_wp, "mismatch <= 1e-6")
  end subroutine test_selfcheck_scales

end module test_hostile
