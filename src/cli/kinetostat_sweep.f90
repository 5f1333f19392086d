!> `kinetostat sweep`: one deck run over a grid of overrides (`--vary NAME=FROM:TO:COUNT`,
!> cartesian product, the first --vary varying slowest), one summary row per variant, in
!> grid order. The variants run in parallel in child processes (`--jobs N`, default: every
!> processor), each child a contiguous block of the grid whose results come back through a
!> temporary file, put together in grid order: the output is the serial run's, byte for byte.
!> Threads (OpenMP) are not used here, because gfortran's run-time library corrupts
!> concurrent internal READ/WRITE (namelist reading, number formatting) - measured, see
!> docs/cli.md "Parameter sweeps". Beyond one machine, sweeps are split over processes
!> (`--part K/N`, xargs -P, GNU parallel, Slurm arrays).
module kinetostat_sweep
  use, intrinsic :: iso_fortran_env, only: error_unit, int64
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_input, out_of_memory
  use kinetostat_text, only: int_str
  use kinetostat_deck, only: deck_source_t, read_group_name
  use kinetostat_override, only: override_t, parse_override, apply_overrides
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_run, only: run_options_t, run_mechanism, format_summary
  use kinetostat_summary, only: summary_header, summary_row, summary_values, override_has_column
  use kinetostat_registry, only: create_mechanism, deck_mechanism
  use kinetostat_npy_writer, only: npy_header, put_npy_values
  use kinetostat_posix, only: fork_process, wait_process, exit_now, temp_anonymous, write_fd, read_fd_at, close_fd
  !$ use omp_lib, only: omp_set_num_threads
  implicit none
  private
  public :: vary_t, parse_vary, run_sweep, variant_result_t, variant_count, allow_selfcheck_failure_in_sweep, sweep_npy
  public :: sweep_header

  !> --allow-selfcheck-failure of the sweep: a variant whose self-check fails warns (else
  !> it fails the sweep, exit 3). Set with allow_selfcheck_failure_in_sweep.
  logical, protected :: sweep_allows_selfcheck_failure = .false.

  !> Largest number of variants a sweep may have.
  integer, parameter :: max_variants = 1000000
  !> Width of a number in the block files of child processes (save_block, load_block).
  integer, parameter :: field_width = 20

  !> One --vary: NAME from FROM to TO in COUNT equal steps (both ends included).
  type :: vary_t
    !> Namelist designator.
    character(len=:), allocatable :: name
    !> First value.
    real(wp) :: from = 0.0_wp
    !> Last value.
    real(wp) :: to = 0.0_wp
    !> Number of values (>= 1; 1 means FROM only).
    integer :: count = 1
  end type vary_t

  !> What one variant came to.
  type :: variant_result_t
    !> Its overrides ("NAME=VALUE" of every --set, then every --vary).
    type(override_t), allocatable :: overrides(:)
    !> Summary CSV header of its run.
    character(len=:), allocatable :: header
    !> Its summary CSV row.
    character(len=:), allocatable :: row
    !> The numbers of that row after the overrides, as computed (summary_values; --format npy).
    real(wp), allocatable :: values(:)
    !> Its warnings, one line each (without the "kinetostat: warning: " prefix).
    type(text_buffer_t) :: warnings
    !> Number of warnings (a failed self-check included).
    integer :: warning_count = 0
    !> Its error, if any.
    type(error_t), allocatable :: error
  end type variant_result_t

contains

  !> A --vary from "NAME=FROM:TO:COUNT".
  subroutine parse_vary(arg, vary, error)
    !> The argument.
    character(*), intent(in) :: arg
    !> The parsed --vary.
    type(vary_t), intent(out) :: vary
    !> Malformed (exit 2).
    type(error_t), allocatable, intent(out) :: error
    type(override_t) :: o
    integer :: c1, c2, ios
    real(wp) :: count
    character(len=:), allocatable :: what
    what = "--vary '"//arg//"': "
    call parse_override(arg, "--vary", o, error)
    if (allocated(error)) then
      error%message = error%message//" (expected NAME=FROM:TO:COUNT)"
      return
    end if
    vary%name = o%name
    c1 = index(o%value, ":")
    c2 = index(o%value, ":", back=.true.)
    if (c1 == 0 .or. c2 == c1) then
      call fatal_error(error, exit_input, what//"expected NAME=FROM:TO:COUNT (e.g. --vary l_ab=0.08:0.14:7)")
      return
    end if
    read (o%value(1:c1 - 1), *, iostat=ios) vary%from
    if (ios == 0) read (o%value(c1 + 1:c2 - 1), *, iostat=ios) vary%to
    if (ios == 0) read (o%value(c2 + 1:), *, iostat=ios) count
    if (ios /= 0) then
      call fatal_error(error, exit_input, what//"FROM, TO and COUNT must be numbers")
    else if (.not. (abs(vary%from) <= huge(1.0_wp) .and. abs(vary%to) <= huge(1.0_wp))) then
      call fatal_error(error, exit_input, what//"FROM and TO must be finite")
    else if (.not. (count >= 1.0_wp .and. count <= real(max_variants, wp) .and. count == aint(count))) then
      call fatal_error(error, exit_input, what//"COUNT must be a whole number from 1 to "//int_str(max_variants))
    else
      vary%count = nint(count)
    end if
  end subroutine parse_vary

  !> Number of variants of a grid, or -1 when it exceeds max_variants.
  pure integer function variant_count(varies)
    type(vary_t), intent(in) :: varies(:)
    integer(int64) :: n
    integer :: i
    n = 1
    do i = 1, size(varies)
      n = n * varies(i)%count
      if (n > max_variants) then
        variant_count = -1
        return
      end if
    end do
    variant_count = int(n)
  end function variant_count

  !> The value of --vary `vary` at index `i` (1..count) as the shortest text that reads back
  !> as the grid value to 14 significant digits (so 0.1:0.2:3 gives 0.15, not
  !> 0.15000000000000002); that text is what the run and the summary use.
  function vary_value(vary, i) result(text)
    type(vary_t), intent(in) :: vary
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    real(wp) :: x, back
    character(len=40) :: buf
    character(len=16) :: fmt
    integer :: digits, ios
    if (vary%count == 1) then
      x = vary%from
    else if (i == vary%count) then
      x = vary%to
    else
      x = vary%from + (vary%to - vary%from) * real(i - 1, wp) / real(vary%count - 1, wp)
    end if
    do digits = 1, 17
      write (fmt, '("(es26.",i0,"e3)")') digits - 1
      write (buf, fmt) x
      read (buf, *, iostat=ios) back
      if (ios /= 0) cycle
      if (abs(back - x) <= 1.0e-14_wp * abs(x) .or. digits == 17) exit
    end do
    text = trim(adjustl(buf))
    call tidy(text)
  end function vary_value

  !> Exponent form "D.DDDe+XXX" as people write numbers: plain decimals from 1e-4 to below
  !> 1e15 ("1.50e-001" -> "0.15", "6.e+001" -> "60"), the exponent form otherwise without
  !> superfluous zeros ("5.e-006" -> "5e-6").
  pure subroutine tidy(text)
    character(len=:), allocatable, intent(inout) :: text
    character(len=:), allocatable :: sign, digits
    integer :: e, ex, ios, n
    e = scan(text, "eE")
    if (e == 0) return
    read (text(e + 1:), *, iostat=ios) ex
    if (ios /= 0) return
    sign = ""
    if (text(1:1) == "-") sign = "-"
    digits = text(len(sign) + 1:e - 1)
    n = index(digits, ".")
    if (n > 0) digits = digits(1:n - 1)//digits(n + 1:)
    n = len(digits)
    do while (n > 1 .and. digits(n:n) == "0")
      n = n - 1
    end do
    digits = digits(1:n)
    if (digits == "0") then
      text = "0"
    else if (ex >= 15 .or. ex < -4) then
      text = sign//digits(1:1)
      if (len(digits) > 1) text = text//"."//digits(2:)
      text = text//"e"//int_str(ex)
    else if (ex < 0) then
      text = sign//"0."//repeat("0", -ex - 1)//digits
    else if (len(digits) <= ex + 1) then
      text = sign//digits//repeat("0", ex + 1 - len(digits))
    else
      text = sign//digits(1:ex + 1)//"."//digits(ex + 2:)
    end if
  end subroutine tidy

  !> Run every variant of the grid on the deck. `results(v)` is variant v (the first
  !> --vary varies slowest). `progress` shows a line on stderr (carriage return,
  !> overwritten) after the first second.
  subroutine run_sweep(source, sets, varies, part, parts, jobs, progress, first, results, error, shaking)
    !> The deck as read.
    type(deck_source_t), intent(in) :: source
    !> The --set overrides (applied before every --vary).
    type(override_t), intent(in) :: sets(:)
    !> The --vary grid axes.
    type(vary_t), intent(in) :: varies(:)
    !> This process runs part `part` of `parts` equal contiguous blocks of the grid (1, 1:
    !> all of it); concatenated in part order, the parts' outputs are the whole grid's.
    integer, intent(in) :: part, parts
    !> Number of processes to run the variants in (1: this one only).
    integer, intent(in) :: jobs
    !> Whether to show a progress line (stderr is a terminal).
    logical, intent(in) :: progress
    !> Grid number of results(1) (the variants of this part are first, first+1, ...).
    integer, intent(out) :: first
    !> One result per variant of this part.
    type(variant_result_t), allocatable, intent(out) :: results(:)
    !> Deck-level error (no group, unknown mechanism, grid too large).
    type(error_t), allocatable, intent(out) :: error
    !> Whether each variant adds the shaking columns (--shaking) to its summary.
    logical, intent(in), optional :: shaking
    character(len=:), allocatable :: group
    class(mechanism_t), allocatable :: probe
    logical :: with_shaking
    integer :: n, v, done, last, stat
    integer(int64) :: start, rate
    logical :: shown
    with_shaking = .false.
    if (present(shaking)) with_shaking = shaking
    call deck_mechanism(source, group, probe, error)
    if (allocated(error)) return
    n = variant_count(varies)
    if (n < 0) then
      call fatal_error(error, exit_input, "sweep: more than "//int_str(max_variants)//" variants")
      return
    end if
    first = int(int(n, int64) * (part - 1) / parts) + 1
    last = int(int(n, int64) * part / parts)
    allocate (results(last - first + 1), stat=stat)
    if (stat /= 0) then
      call out_of_memory(error, "the results of "//int_str(last - first + 1)//" sweep variants", &
        int(last - first + 1, int64) * storage_size(results) / 8)
      return
    end if
    do v = first, last
      results(v - first + 1)%overrides = variant_overrides(sets, varies, v)
    end do
    if (jobs > 1 .and. size(results) > 1) then
      call run_in_children(source, group, min(jobs, size(results)), results, with_shaking)
      return
    end if
    done = 0
    shown = .false.
    call system_clock(start, rate)
    do v = 1, size(results)
      call run_variant(source, group, results(v), with_shaking)
      done = done + 1
      if (progress) call show_progress(done, size(results), start, rate, shown)
    end do
    if (shown) write (error_unit, '(a)') ""
  end subroutine run_sweep

  !> The variants in `jobs` child processes, each a contiguous block, its results returned
  !> through an anonymous temporary file (made in $TMPDIR before the fork and unlinked at
  !> once, so nothing is left whatever ends the processes; a fatal signal to this process
  !> ends the children too). A block whose child could not be started or did not return
  !> its results is run here instead, so the results are always complete and in grid order.
  subroutine run_in_children(source, group, jobs, results, shaking)
    type(deck_source_t), intent(in) :: source
    character(*), intent(in) :: group
    !> Number of child processes (2 .. size(results)).
    integer, intent(in) :: jobs
    !> One result per variant (overrides set), filled here.
    type(variant_result_t), intent(inout) :: results(:)
    !> Whether the variants add the shaking columns.
    logical, intent(in) :: shaking
    integer :: pids(jobs), files(jobs), j, lo, hi, v, n, err
    logical :: ok
    n = size(results)
    do j = 1, jobs
      lo = block_start(j)
      hi = block_start(j + 1) - 1
      pids(j) = -1
      files(j) = temp_anonymous()
      if (files(j) < 0) cycle
      pids(j) = fork_process()
      if (pids(j) == 0) then
        !$ call omp_set_num_threads(1)
        do v = lo, hi
          call run_variant(source, group, results(v), shaking)
        end do
        call save_block(files(j), results(lo:hi), ok)
        call exit_now(merge(0, 1, ok))
      end if
    end do
    do j = 1, jobs
      lo = block_start(j)
      hi = block_start(j + 1) - 1
      ok = .false.
      if (pids(j) > 0) then
        if (wait_process(pids(j)) == 0) call load_block(files(j), results(lo:hi), ok)
      end if
      if (files(j) >= 0) err = close_fd(files(j))
      if (ok) cycle
      do v = lo, hi
        call run_variant(source, group, results(v), shaking)
      end do
    end do
  contains
    !> First variant of block `j` (block jobs + 1 starts after the last variant).
    integer function block_start(j)
      integer, intent(in) :: j
      block_start = int(int(n, int64) * (j - 1) / jobs) + 1
    end function block_start
  end subroutine run_in_children

  !> Write the results of a block to descriptor `fd` (read back by load_block): per variant
  !> "E" code, message or "R" header, row, warning count, warnings, the count of the row's
  !> numbers and their 8 bytes each; each text after its length (field_width digits).
  subroutine save_block(fd, results, ok)
    integer, intent(in) :: fd
    type(variant_result_t), intent(in) :: results(:)
    logical, intent(out) :: ok
    type(text_buffer_t) :: buf
    character(len=8) :: value_bytes
    integer :: v, i
    value_bytes = ""
    do v = 1, size(results)
      associate (r => results(v))
        if (allocated(r%error)) then
          call buf%append("E"//field(r%error%code)//field(len(r%error%message))//r%error%message)
        else
          call buf%append("R"//field(len(r%header))//r%header//field(len(r%row))//r%row// &
            field(r%warning_count)//field(r%warnings%length))
          if (r%warnings%length > 0) call buf%append(r%warnings%data(1:r%warnings%length))
          ! the numbers as their bytes (exactly as computed)
          call buf%append(field(size(r%values)))
          do i = 1, size(r%values)
            call buf%append(transfer(r%values(i), value_bytes))
          end do
        end if
      end associate
    end do
    ok = .true.
    if (buf%length > 0) ok = write_fd(fd, buf%data(1:buf%length)) == 0
  end subroutine save_block

  !> A number as a field of save_block.
  function field(n) result(text)
    integer, intent(in) :: n
    character(len=field_width) :: text
    write (text, '(i20)') n
  end function field

  !> Read the results of a block written by save_block to descriptor `fd`.
  subroutine load_block(fd, results, ok)
    integer, intent(in) :: fd
    type(variant_result_t), intent(inout) :: results(:)
    logical, intent(out) :: ok
    character(len=:), allocatable :: text, chunk
    integer(int64) :: got, offset
    integer :: v, p, length, code, i
    ok = .false.
    text = ""
    offset = 0
    do
      got = read_fd_at(fd, 65536, offset, chunk)
      if (got < 0) return
      if (got == 0) exit
      text = text//chunk
      offset = offset + got
    end do
    p = 1
    do v = 1, size(results)
      associate (r => results(v))
        if (p > len(text)) return
        if (text(p:p) == "E") then
          p = p + 1
          if (.not. (number(code) .and. number(length))) return
          if (p + length - 1 > len(text)) return
          allocate (r%error)
          r%error%code = code
          r%error%message = text(p:p + length - 1)
          p = p + length
        else if (text(p:p) == "R") then
          p = p + 1
          if (.not. number(length)) return
          if (p + length - 1 > len(text)) return
          r%header = text(p:p + length - 1)
          p = p + length
          if (.not. number(length)) return
          if (p + length - 1 > len(text)) return
          r%row = text(p:p + length - 1)
          p = p + length
          if (.not. (number(r%warning_count) .and. number(length))) return
          if (p + length - 1 > len(text)) return
          if (length > 0) then
            r%warnings%data = text(p:p + length - 1)
            r%warnings%length = length
          end if
          p = p + length
          if (.not. number(length)) return
          if (p + 8 * length - 1 > len(text)) return
          allocate (r%values(length))
          do i = 1, length
            r%values(i) = transfer(text(p:p + 7), 1.0_wp)
            p = p + 8
          end do
        else
          return
        end if
      end associate
    end do
    ok = p == len(text) + 1
  contains
    !> The next field as a number (false when malformed or past the end).
    logical function number(n)
      integer, intent(out) :: n
      integer :: ios
      number = .false.
      n = 0
      if (p + field_width - 1 > len(text)) return
      read (text(p:p + field_width - 1), '(i20)', iostat=ios) n
      if (ios /= 0 .or. n < 0) return
      p = p + field_width
      number = .true.
    end function number
  end subroutine load_block

  !> The overrides of variant v: the --set ones, then one per --vary.
  function variant_overrides(sets, varies, v) result(overrides)
    type(override_t), intent(in) :: sets(:)
    type(vary_t), intent(in) :: varies(:)
    integer, intent(in) :: v
    type(override_t), allocatable :: overrides(:)
    integer :: i, k, rest, index_i
    character(len=:), allocatable :: value
    allocate (overrides(size(sets) + size(varies)))
    do k = 1, size(sets)
      overrides(k) = sets(k)
    end do
    rest = v - 1
    do i = size(varies), 1, -1
      index_i = mod(rest, varies(i)%count) + 1
      rest = rest / varies(i)%count
      value = vary_value(varies(i), index_i)
      k = size(sets) + i
      overrides(k)%name = varies(i)%name
      overrides(k)%value = value
    end do
  end function variant_overrides

  !> Whether a sweep's variants may fail their self-check with a warning only.
  subroutine allow_selfcheck_failure_in_sweep(allowed)
    !> --allow-selfcheck-failure was given.
    logical, intent(in) :: allowed
    sweep_allows_selfcheck_failure = allowed
  end subroutine allow_selfcheck_failure_in_sweep

  !> The sweep's summary header: that of the first variant of the grid that runs, the same in
  !> every --part (a variant outside this part's `results` is run here to find it), so that
  !> it does not depend on which of this part's variants succeed; when no variant of the grid
  !> runs, the header of the deck with the --set overrides only, under the variants' column
  !> names; "" when that fails too.
  subroutine sweep_header(source, sets, varies, first, results, shaking, header)
    type(deck_source_t), intent(in) :: source
    type(override_t), intent(in) :: sets(:)
    type(vary_t), intent(in) :: varies(:)
    !> Grid number of results(1).
    integer, intent(in) :: first
    !> This part's results.
    type(variant_result_t), intent(in) :: results(:)
    !> Whether the variants add the shaking columns.
    logical, intent(in) :: shaking
    character(len=:), allocatable, intent(out) :: header
    type(variant_result_t) :: probe
    type(error_t), allocatable :: error
    character(len=:), allocatable :: group
    integer :: v
    header = ""
    call read_group_name(source, group, error)
    if (allocated(error)) return
    do v = 1, variant_count(varies)
      if (v >= first .and. v < first + size(results)) then
        if (allocated(results(v - first + 1)%error)) cycle
        header = results(v - first + 1)%header
        return
      end if
      probe = variant_result_t()
      probe%overrides = variant_overrides(sets, varies, v)
      call run_variant(source, group, probe, shaking)
      if (allocated(probe%error)) cycle
      header = probe%header
      return
    end do
    probe = variant_result_t()
    probe%overrides = variant_overrides(sets, varies, 1)
    call run_variant(source, group, probe, shaking, sets)
    if (.not. allocated(probe%error)) header = probe%header
  end subroutine sweep_header

  !> One variant: the deck with its overrides through the one run pipeline.
  subroutine run_variant(source, group, result, shaking, deck_overrides)
    type(deck_source_t), intent(in) :: source
    character(*), intent(in) :: group
    type(variant_result_t), intent(inout) :: result
    !> Whether to add the shaking columns (--shaking).
    logical, intent(in) :: shaking
    !> The overrides written into the deck, when not all of result%overrides (which still
    !> name the summary's columns).
    type(override_t), intent(in), optional :: deck_overrides(:)
    type(deck_source_t) :: patched
    class(mechanism_t), allocatable :: mech
    type(run_options_t) :: options
    type(step_table_t) :: table
    type(text_buffer_t) :: out
    logical, allocatable :: whole(:)
    integer :: i
    if (present(deck_overrides)) then
      call apply_overrides(source, deck_overrides, patched, result%error)
    else
      call apply_overrides(source, result%overrides, patched, result%error)
    end if
    if (allocated(result%error)) return
    call create_mechanism(group, mech)
    options%format = format_summary
    options%rows_unread = .true.
    options%shaking = shaking
    options%overrides = result%overrides
    options%allow_selfcheck_failure = sweep_allows_selfcheck_failure
    call run_mechanism(mech, group, patched, options, table, out, result%error)
    if (allocated(result%error)) return
    result%header = summary_header(table, .false.)
    result%row = summary_row(table, .false.)
    call summary_values(table, .false., result%values, whole)
    do i = 1, table%warning_count()
      call result%warnings%put(table%warnings(i)%text)
    end do
    result%warning_count = table%warning_count()
  end subroutine run_variant

  !> The sweep's rows as an npy file (--format npy): the columns of its summary CSV header,
  !> each a float64 field of that name, one record per variant: an override column whose
  !> value is one number (every --vary, a --set of a number) with that number, the rest as
  !> computed (summary_values). A --set whose value is not one number (a text, a list) is
  !> the same in every row and is left out.
  subroutine sweep_npy(results, out, error)
    !> The variants, none failed, all with the same header.
    type(variant_result_t), intent(in) :: results(:)
    !> Where the bytes go.
    type(text_buffer_t), intent(inout) :: out
    !> The header and the numbers do not match (a bug).
    type(error_t), allocatable, intent(out) :: error
    character(len=len(results(1)%header)) :: flat
    integer :: ends(len(results(1)%header) + 1)
    !> The header's fields kept (the override columns of one number, every figure), and
    !> where each field's value comes from: override j (> 0) or figure -k.
    integer, allocatable :: kept(:), source(:)
    real(wp), allocatable :: row(:)
    real(wp) :: x
    integer :: n_over, v, j, n_fields, field
    logical :: numeric
    logical :: has(size(results(1)%overrides))
    call csv_split(results(1)%header, flat, ends, n_fields)
    n_over = size(results(1)%overrides)
    ! a variable set twice has one column, the later override's
    has = override_has_column(override_names(results(1)))
    if (n_fields /= count(has) + size(results(1)%values)) then
      call fatal_error(error, exit_input, "sweep: --format npy: "//int_str(n_fields)//" summary columns but "// &
        int_str(count(has) + size(results(1)%values))//" values (a bug: please report it)")
      return
    end if
    allocate (kept(0), source(0))
    field = 0
    do j = 1, n_over
      if (.not. has(j)) cycle
      field = field + 1
      numeric = .true.
      do v = 1, size(results)
        numeric = numeric .and. one_number(results(v)%overrides(j)%value, x)
      end do
      if (numeric) then
        kept = [kept, field]
        source = [source, j]
      end if
    end do
    kept = [kept, [(field + j, j = 1, size(results(1)%values))]]
    source = [source, [(-j, j = 1, size(results(1)%values))]]
    call out%append(kept_header(flat, ends, kept, size(results)))
    allocate (row(size(kept)))
    do v = 1, size(results)
      do j = 1, size(kept)
        if (source(j) > 0) then
          numeric = one_number(results(v)%overrides(source(j))%value, row(j))
        else
          row(j) = results(v)%values(-source(j)) + 0.0_wp
        end if
      end do
      call put_npy_values(out, row)
    end do
  contains
    !> The variant's overrides as "NAME=" (override_has_column compares the names).
    pure function override_names(r) result(names)
      type(variant_result_t), intent(in) :: r
      character(len=:), allocatable :: names(:)
      integer :: k, longest
      longest = 1
      do k = 1, size(r%overrides)
        longest = max(longest, len(r%overrides(k)%name) + 1)
      end do
      allocate (character(len=longest) :: names(size(r%overrides)))
      do k = 1, size(r%overrides)
        names(k) = r%overrides(k)%name//"="
      end do
    end function override_names
  end subroutine sweep_npy

  !> Whether `text` is one number (digits, sign, point, exponent; no repeat count, list or
  !> text), and its value.
  logical function one_number(text, x)
    character(*), intent(in) :: text
    real(wp), intent(out) :: x
    integer :: ios
    x = 0.0_wp
    one_number = .false.
    if (len_trim(text) == 0 .or. verify(trim(adjustl(text)), "0123456789+-.eEdD") /= 0) return
    read (text, *, iostat=ios) x
    one_number = ios == 0
  end function one_number

  !> The fields of a CSV line (quoted fields unquoted, "" inside them as one "): their
  !> characters one after the other in `flat`, field i ending at ends(i) (starting after
  !> ends(i - 1)); `count` fields.
  pure subroutine csv_split(line, flat, ends, count)
    character(*), intent(in) :: line
    !> The fields' characters (as long as `line`).
    character(len=len(line)), intent(out) :: flat
    !> At least len(line) + 1 entries.
    integer, intent(out) :: ends(:)
    integer, intent(out) :: count
    integer :: i, n
    logical :: quoted
    count = 0
    n = 0
    flat = ""
    quoted = .false.
    i = 1
    do while (i <= len(line))
      if (line(i:i) == '"' .and. quoted .and. i < len(line)) then
        if (line(i + 1:i + 1) == '"') then
          n = n + 1
          flat(n:n) = '"'
          i = i + 2
          cycle
        end if
      end if
      if (line(i:i) == '"') then
        quoted = .not. quoted
      else if (line(i:i) == "," .and. .not. quoted) then
        count = count + 1
        ends(count) = n
      else
        n = n + 1
        flat(n:n) = line(i:i)
      end if
      i = i + 1
    end do
    count = count + 1
    ends(count) = n
  end subroutine csv_split

  !> npy_header of the fields kept(:) of a split CSV line (csv_split), `rows` records.
  pure function kept_header(flat, ends, kept, rows) result(text)
    character(*), intent(in) :: flat
    integer, intent(in) :: ends(:), kept(:), rows
    character(len=:), allocatable :: text
    integer :: starts(size(kept)), lengths(size(kept)), j
    do j = 1, size(kept)
      starts(j) = 1
      if (kept(j) > 1) starts(j) = ends(kept(j) - 1) + 1
      lengths(j) = ends(kept(j)) - starts(j) + 1
    end do
    text = named_header(flat, starts, lengths, max(1, maxval(lengths)), rows)
  end function kept_header

  !> npy_header of the names flat(starts(j):starts(j) + lengths(j) - 1).
  pure function named_header(flat, starts, lengths, longest, rows) result(text)
    character(*), intent(in) :: flat
    integer, intent(in) :: starts(:), lengths(:), longest, rows
    character(len=:), allocatable :: text
    character(len=longest) :: names(size(starts))
    integer :: j
    do j = 1, size(starts)
      names(j) = flat(starts(j):starts(j) + lengths(j) - 1)
    end do
    text = npy_header(names, lengths, rows)
  end function named_header

  !> "kinetostat: sweep: 37/120 variants, 12 s" on stderr, overwritten in place; only
  !> after the first second.
  subroutine show_progress(done, n, start, rate, shown)
    integer, intent(in) :: done, n
    integer(int64), intent(in) :: start, rate
    logical, intent(inout) :: shown
    integer(int64) :: now
    call system_clock(now)
    if (rate <= 0) return
    if (now - start < rate) return
    write (error_unit, '(a)', advance='no') achar(13)//"kinetostat: sweep: "//int_str(done)//"/"// &
      int_str(n)//" variants, "//int_str(int((now - start) / rate))//" s"
    flush (error_unit)
    shown = .true.
  end subroutine show_progress

end module kinetostat_sweep
