!> The command line, defined once: every option (its names, its value, the values it takes)
!> and every subcommand (its operands and its options in synopsis order). The parser takes
!> from this table which options exist, which take a value and which belong to a subcommand;
!> --help's synopsis and the usage line are written from it. test/cli/test_options.sh checks
!> the man page and the bash completion against --help.
module kinetostat_cli_options
  use kinetostat_run, only: format_names
  use kinetostat_labels, only: lang_names
  use kinetostat_assur_balance, only: balance_method_names
  use kinetostat_text, only: joined
  implicit none
  private
  public :: option_t, command_t, cli_options, cli_commands, find_option, find_command, value_options, &
    command_takes, synopsis_lines, usage_text, frame_names, choice_text

  !> Longest option word of a command ("--format=summary|npy").
  integer, parameter :: word_room = 40
  !> Longest line of synopsis_lines.
  integer, parameter :: synopsis_room = 240

  !> The values of --frame.
  character(*), parameter :: frame_names(*) = [character(len=6) :: "global", "link"]

  !> An option.
  type :: option_t
    !> Long name ("--format").
    character(len=26) :: name = ""
    !> Short name ("-o"), or blank.
    character(len=2) :: short = ""
    !> What its value is ("FILE", "K/N"); blank for a flag or an option of choices.
    character(len=20) :: value = ""
    !> The values it takes, "|" between ("en|ru"); blank for any.
    character(len=80) :: choices = ""
    !> Given more than once, each counts ("..." after it in the synopsis).
    logical :: repeated = .false.
  end type option_t

  !> A subcommand.
  type :: command_t
    !> Its word ("sweep"); blank for the run of a deck.
    character(len=10) :: name = ""
    !> Its operands as the synopsis shows them ("DECK|-", "A B").
    character(len=8) :: operands = ""
    !> Its options in synopsis order, a blank between: each by the name the synopsis shows
    !> ("-o" for -o/--output); "NAME!" is required (no brackets); "NAME=A|B" (or "-o=DIR") shows these
    !> of the option's values here.
    character(len=300) :: options = ""
  end type command_t

contains

  !> Every option.
  pure function cli_options() result(table)
    type(option_t), allocatable :: table(:)
    table = [ &
      option_t("--set", "", "NAME=VALUE", "", .true.), &
      option_t("--output", "-o", "FILE"), &
      option_t("--format", "", "", choice_text(format_names)), &
      option_t("--pairs", "", "LIST"), &
      option_t("--at", "", "K"), &
      option_t("--plans"), &
      option_t("--lang", "", "", joined(lang_names, "|")), &
      option_t("--kinematics"), &
      option_t("--frame", "", "", joined(frame_names, "|")), &
      option_t("--shaking"), &
      option_t("--student", "", "NAME"), &
      option_t("--group", "", "G"), &
      option_t("--variant", "", "N"), &
      option_t("--max-deck-size", "", "BYTES"), &
      option_t("--allow-selfcheck-failure"), &
      option_t("--quiet", "-q"), &
      option_t("--strict"), &
      option_t("--vary", "", "NAME=FROM:TO:COUNT", "", .true.), &
      option_t("--part", "", "K/N"), &
      option_t("--jobs", "", "N"), &
      option_t("--keep-going"), &
      option_t("--method", "", "", joined(balance_method_names, "|")), &
      option_t("--fraction", "", "F"), &
      option_t("--to", "", "", "linkage"), &
      option_t("--rtol", "", "R"), &
      option_t("--atol", "", "A"), &
      option_t("--common"), &
      option_t("--paper", "", "", "A1|A2|A3|A4"), &
      option_t("--designation", "", "TEXT"), &
      option_t("--sheet-numbers", "", "N,N,..."), &
      option_t("--positions", "", "", "8|12"), &
      option_t("--point", "", "NAME"), &
      option_t("--output-link", "", "I"), &
      option_t("--help", "-h"), &
      option_t("--version", "-V")]
  end function cli_options

  !> Every subcommand, the run of a deck first.
  pure function cli_commands() result(table)
    type(command_t), allocatable :: table(:)
    table = [ &
      command_t("", "DECK|-", "--set -o --format --pairs --at --plans --lang --kinematics --frame --shaking " // &
        "--student --group --variant --max-deck-size --allow-selfcheck-failure --quiet --strict"), &
      command_t("sweep", "DECK", "--vary! --set --part --jobs --keep-going --format=summary|npy --shaking -o " // &
        "--max-deck-size --allow-selfcheck-failure --quiet --strict"), &
      command_t("template", "KIND", "-o"), &
      command_t("diff", "A B", "--rtol --atol --common --quiet"), &
      command_t("balance", "DECK", "-o --method --fraction --lang --max-deck-size --quiet"), &
      command_t("structure", "DECK", "--lang -o --max-deck-size --quiet"), &
      command_t("convert", "DECK", "--to! -o --max-deck-size --quiet"), &
      command_t("contour", "DECK", "--set -o --max-deck-size --quiet"), &
      command_t("sheets", "DECK", "-o!=DIR --paper --lang --at --designation --sheet-numbers --positions --point " // &
        "--output-link --student --group --variant --set --max-deck-size --quiet")]
  end function cli_commands

  !> A list "a, b, c" as choices "a|b|c".
  pure function choice_text(names) result(text)
    !> The names, ", " between.
    character(*), intent(in) :: names
    character(len=:), allocatable :: text
    integer :: i
    text = names
    do
      i = index(text, ", ")
      if (i == 0) exit
      text = text(:i - 1)//"|"//text(i + 2:)
    end do
  end function choice_text

  !> The index in cli_options() of an option by its long or short name; 0 if none.
  pure integer function find_option(name) result(k)
    character(*), intent(in) :: name
    type(option_t), allocatable :: table(:)
    allocate (table(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    table = cli_options()
    do k = 1, size(table)
      if (name == trim(table(k)%name) .or. (len_trim(name) > 0 .and. name == trim(table(k)%short))) return
    end do
    k = 0
  end function find_option

  !> The index in cli_commands() of a subcommand by its word ("" the run of a deck); 0 if none.
  pure integer function find_command(name) result(k)
    character(*), intent(in) :: name
    character(len=10), allocatable :: words(:)
    allocate (words(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    words = command_names()
    k = findloc(words, name, dim=1)
  end function find_command

  !> The subcommands' words in the order of cli_commands().
  pure function command_names() result(words)
    character(len=10), allocatable :: words(:)
    type(command_t), allocatable :: table(:)
    allocate (table(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    table = cli_commands()
    words = table%name
  end function command_names

  !> The names (long and short) of the options that take a value.
  pure function value_options() result(names)
    character(len=26), allocatable :: names(:)
    type(option_t), allocatable :: table(:)
    integer :: k
    allocate (table(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    table = cli_options()
    allocate (names(0))
    do k = 1, size(table)
      if (len_trim(table(k)%value) == 0 .and. len_trim(table(k)%choices) == 0) cycle
      names = [character(len=26) :: names, table(k)%name]
      if (len_trim(table(k)%short) > 0) names = [character(len=26) :: names, table(k)%short]
    end do
  end function value_options

  !> Whether subcommand `command` (an index of cli_commands()) takes option `option` (an
  !> index of cli_options()); --help and --version go with every one.
  pure logical function command_takes(command, option)
    integer, intent(in) :: command, option
    type(option_t), allocatable :: options(:)
    character(len=word_room), allocatable :: words(:)
    integer :: w
    allocate (options(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    options = cli_options()
    command_takes = any(trim(options(option)%name) == ["--help   ", "--version"])
    if (command_takes) return
    allocate (words(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    words = command_words(command)
    do w = 1, size(words)
      command_takes = find_option(bare(trim(words(w)))) == option
      if (command_takes) return
    end do
  end function command_takes

  !> The option words of a command, one an element.
  pure function command_words(command) result(words)
    integer, intent(in) :: command
    character(len=word_room), allocatable :: words(:)
    type(command_t), allocatable :: commands(:)
    character(len=:), allocatable :: text
    integer :: blank
    allocate (commands(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    commands = cli_commands()
    text = trim(commands(command)%options)//" "
    allocate (words(0))
    do while (len_trim(text) > 0)
      blank = index(text, " ")
      words = [character(len=word_room) :: words, text(:blank - 1)]
      text = text(blank + 1:)
    end do
  end function command_words

  !> An option word of a command without its marks ("--vary!" -> "--vary",
  !> "--format=summary|npy" -> "--format").
  pure function bare(word) result(name)
    character(*), intent(in) :: word
    character(len=:), allocatable :: name
    ! (a word without marks ends at the "=" added)
    name = word(:scan(word//"=", "!=") - 1)
  end function bare

  !> One option word of a command as the synopsis shows it ("[--format table|csv]",
  !> "--vary NAME=FROM:TO:COUNT...").
  pure function option_synopsis(word) result(text)
    character(*), intent(in) :: word
    character(len=:), allocatable :: text
    type(option_t) :: opt
    type(option_t), allocatable :: table(:)
    character(len=:), allocatable :: name
    logical :: required
    integer :: eq
    allocate (table(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    table = cli_options()
    name = bare(word)
    opt = table(find_option(name))
    required = index(word, "!") > 0
    eq = index(word, "=")
    text = name
    if (eq > 0) then
      text = text//" "//word(eq + 1:)
    else if (len_trim(opt%choices) > 0) then
      text = text//" "//trim(opt%choices)
    else if (len_trim(opt%value) > 0) then
      text = text//" "//trim(opt%value)
    end if
    if (.not. required) text = "["//text//"]"
    if (opt%repeated) text = text//"..."
  end function option_synopsis

  !> The synopsis of every subcommand for --help: a line each, continued on lines indented
  !> to column 19 when longer than `width`; the last line "kinetostat --help | --version".
  pure function synopsis_lines(width) result(lines)
    !> Longest line (at most synopsis_room).
    integer, intent(in) :: width
    character(len=synopsis_room), allocatable :: lines(:)
    integer :: c
    allocate (lines(0))
    do c = 1, size(cli_commands())
      lines = [character(len=synopsis_room) :: lines, command_lines(c, width)]
    end do
    lines = [character(len=synopsis_room) :: lines, "  kinetostat --help | --version"]
  end function synopsis_lines

  !> The synopsis of subcommand `c` (an index of cli_commands()), "  kinetostat ...", in
  !> lines of at most `width` (continuations indented to column 19).
  pure function command_lines(c, width) result(lines)
    integer, intent(in) :: c, width
    character(len=synopsis_room), allocatable :: lines(:)
    type(command_t), allocatable :: commands(:)
    character(len=:), allocatable :: line, piece
    character(len=word_room), allocatable :: words(:)
    integer :: w
    allocate (commands(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    commands = cli_commands()
    allocate (lines(0))
    line = "  kinetostat "
    if (len_trim(commands(c)%name) > 0) line = line//trim(commands(c)%name)//" "
    line = line//trim(commands(c)%operands)
    allocate (words(0)) ! defined before the assignment (gcc's -Wuninitialized on the descriptor)
    words = command_words(c)
    do w = 1, size(words)
      piece = option_synopsis(trim(words(w)))
      if (len(line) + 1 + len(piece) > width) then
        lines = [character(len=synopsis_room) :: lines, line]
        line = repeat(" ", 17)
      end if
      line = line//" "//piece
    end do
    lines = [character(len=synopsis_room) :: lines, line]
  end function command_lines

  !> The synopses of `lines` on one line, " | " between: "kinetostat sweep DECK ... | ...".
  pure function one_line(lines) result(text)
    character(*), intent(in) :: lines(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ""
    do i = 1, size(lines)
      if (i > 1) then
        if (lines(i)(1:3) /= "   ") text = text//" |"
        text = text//" "
      end if
      text = text//trim(adjustl(lines(i)))
    end do
  end function one_line

  !> The usage line printed with a usage error: "usage: " and every synopsis, " | " between;
  !> with `command`, that subcommand's only ("usage: kinetostat diff A B ...").
  pure function usage_text(command) result(text)
    !> A subcommand's word.
    character(*), intent(in), optional :: command
    character(len=:), allocatable :: text
    if (present(command)) then
      text = "usage: "//one_line(command_lines(find_command(command), synopsis_room))
    else
      text = "usage: "//one_line(synopsis_lines(synopsis_room))
    end if
  end function usage_text

end module kinetostat_cli_options
