!> The benchmark of kinetostat (not a test: it prints figures, it never fails on them).
!>
!>   fpm run --profile release --example bench [-- [MAX_STEPS] [KIND...]]
!>
!> For every stepped mechanism (a bundled deck scaled in memory to 10^4, 10^5 and 10^6 steps,
!> up to MAX_STEPS) it prints the solve rates (kernel and step table, steps/s; "kernel" without
!> the kinematics columns, as a plain run, "solve" with them), the end-to-end
!> rate of CSV, the legacy table, JSON and npy written to a file (deck text -> output file, the
!> pipeline of `kinetostat DECK -o FILE`), the peak resident memory of each end-to-end run
!> (VmHWM of /proc/self/status after resetting it through /proc/self/clear_refs), and every
!> rate as a fraction of the physical-limit estimate of one dedicated step on one core.
!> Rates are steps per second of processor time (the machine may be shared: wall time would
!> measure the other processes too), with one thread as the program runs by default. Then,
!> with OpenMP and more than one processor, the parallel steps: wall time of the end-to-end
!> CSV and table runs at the largest step count with one thread and with every processor,
!> the speed-up, and what Amdahl's law makes of it for 4 and 8 cores and for any number.
!> With pr3207 or assur wanted, the cost of the machine dynamics stage: a 10^5-step run (or
!> MAX_STEPS if smaller) over one turn of the deck with its flywheel (data/pr3207_flywheel.nml,
!> data/assur_pr3207_flywheel.nml) against the same steps of the plain deck, solve alone and
!> CSV end to end, and their ratio.
!> Last (kind `linkage`, or no kind), the general linkage engine's solve per step against the
!> dyad engine's (bench_linkage).
!> Run from the project root (it reads data/*.nml).
program bench
  !$ use omp_lib, only: omp_set_num_threads, omp_get_num_procs
  use, intrinsic :: iso_fortran_env, only: int64, output_unit
  use, intrinsic :: iso_c_binding, only: c_int, c_size_t
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_deck, only: deck_source_t, deck_source_from_text, load_deck, read_group_name, deck_line_count, deck_line
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_registry, only: create_mechanism
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_run, only: run_options_t, run_mechanism, format_csv, format_table, format_json, format_npy, block_rows
  use kinetostat_spool, only: spool_t
  use kinetostat_decimal, only: put_es_compact, edit_f
  use kinetostat_csv_writer, only: write_csv
  use kinetostat_json_writer, only: write_json
  use kinetostat_table_writer, only: write_table_rows
  use kinetostat_labels, only: lang_en
  implicit none

  !> Physical-limit estimate of one dedicated step on one core, steps/s: ~300 flops and ~15
  !> sin/atan2 calls of 10-11 ns each.
  real(wp), parameter :: limit_rate = 2.0e6_wp
  !> Step counts of the runs.
  integer, parameter :: step_counts(*) = [10000, 100000, 1000000]
  !> Row format: kind, steps, kernel and solve rates, four end-to-end rates, four peaks, ratios.
  character(*), parameter :: row_fmt = '(a8,i9,6es10.2,4f8.1,6f7.3)'
  !> Header lines of the table.
  character(*), parameter :: header(*) = [character(len=160) :: &
    "                  steps per CPU second (kernel, solve: see below)                     peak MiB" // &
    "                             ratio to limit", &
    "    kind    steps    kernel     solve       csv     table      json       npy     csv   table    json     npy" // &
    " kernel  solve    csv  table   json    npy"]

  interface
    !> glibc: give the heap's free memory back to the system (so that a peak is the run's own).
    function malloc_trim(pad) bind(c, name="malloc_trim") result(released)
      import :: c_int, c_size_t
      implicit none
      integer(c_size_t), value :: pad
      integer(c_int) :: released
    end function malloc_trim
  end interface

  !> A benchmarked case: the bundled deck and the kind of override its step count needs.
  type :: bench_case_t
    !> Mechanism kind (namelist group).
    character(len=8) :: kind
    !> Bundled deck scaled.
    character(len=32) :: deck
  end type bench_case_t

  type(bench_case_t), parameter :: cases(*) = [ &
    bench_case_t("pr3207", "data/pr3207.nml"), &
    bench_case_t("pr3050", "data/pr3050.nml"), &
    bench_case_t("sixbar", "data/sixbar.nml"), &
    bench_case_t("assur", "data/assur_sixbar.nml"), &
    bench_case_t("cam", "data/cam_flat.nml")]

  character(len=:), allocatable :: out_path, arg
  integer :: max_steps, i, j, length
  logical :: any_kind, wanted(size(cases))

  max_steps = step_counts(size(step_counts))
  any_kind = .false.
  wanted = .false.
  do i = 1, command_argument_count()
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: arg)
    call get_command_argument(i, arg)
    if (verify(arg, "0123456789") == 0 .and. length > 0) then
      read (arg, *) max_steps
    else
      any_kind = .true.
      wanted = wanted .or. cases%kind == arg
    end if
    deallocate (arg)
  end do
  if (.not. any_kind) wanted = .true.
  out_path = "/tmp/kinetostat-bench.out"

  ! one thread, as `kinetostat` runs without OMP_NUM_THREADS
  !$ call omp_set_num_threads(1)
  call bench_writer()
  call bench_text()
  write (output_unit, '(a,es8.1,a)') "kinetostat bench: physical-limit estimate ", limit_rate, &
    " steps/s (one dedicated step, one core)"
  do i = 1, size(header)
    write (output_unit, '(a)') trim(header(i))
  end do
  do i = 1, size(cases)
    if (.not. wanted(i)) cycle
    do j = 1, size(step_counts)
      if (step_counts(j) > max_steps) exit
      call bench_one(cases(i), step_counts(j), out_path)
    end do
  end do
  call bench_dynamics(out_path)
  call bench_threads(out_path)
  call bench_linkage(max_steps)
  open (newunit=i, file=out_path, status='old', iostat=j)
  if (j == 0) close (i, status='delete')

contains

  !> The number writer alone: values per CPU second of the compiler's formatted WRITE and of
  !> kinetostat_decimal, for the CSV cell (ES20.12E3) and a table field (F12.2), on 10^6
  !> values of magnitudes 1e-3 .. 1e6 (both signs); the texts are compared as they go.
  subroutine bench_writer()
    integer, parameter :: value_count = 1000000
    real(wp), allocatable :: x(:)
    character(len=32) :: text
    character(len=12) :: field, field2
    real(wp) :: t0, t_write, t_own, f_write, f_own
    integer :: i, pos, differ
    allocate (x(value_count))
    call random_number(x)
    x = 10.0_wp**(9.0_wp * x - 3.0_wp)
    x(2::2) = -x(2::2)
    differ = 0
    t0 = clock()
    do i = 1, value_count
      write (text, '(es20.12e3)') x(i)
    end do
    t_write = seconds_since(t0)
    t0 = clock()
    do i = 1, value_count
      pos = 0
      call put_es_compact(x(i), 12, 3, text, pos)
    end do
    t_own = seconds_since(t0)
    t0 = clock()
    do i = 1, value_count
      write (field, '(f12.2)') x(i)
    end do
    f_write = seconds_since(t0)
    t0 = clock()
    do i = 1, value_count
      call edit_f(x(i), 2, field2)
    end do
    f_own = seconds_since(t0)
    do i = 1, value_count, 97
      write (field, '(f12.2)') x(i)
      call edit_f(x(i), 2, field2)
      if (field /= field2) differ = differ + 1
    end do
    write (output_unit, '(a)') "number writer, values per CPU second (10^6 values, 1e-3 .. 1e6):"
    write (output_unit, '(a,es9.2,a,es9.2,a,f5.1)') "  ES20.12E3  compiler WRITE", value_count / t_write, &
      "   kinetostat_decimal", value_count / t_own, "   x", t_write / t_own
    write (output_unit, '(a,es9.2,a,es9.2,a,f5.1)') "  F12.2      compiler WRITE", value_count / f_write, &
      "   kinetostat_decimal", value_count / f_own, "   x", f_write / f_own
    if (differ > 0) write (output_unit, '(a,i0)') "  texts that differ (a bug): ", differ
  end subroutine bench_writer

  !> Text output alone (the decimal writer and the row assembly of the CSV, JSON and legacy
  !> table writers): for PR 3207 and the generic six-bar (when wanted), one block of
  !> block_rows steps solved with the kinematics columns shown (as --kinematics), then its
  !> rows formatted again and again for about half a CPU second per writer; cells (rows times
  !> the columns the CSV shows) per CPU second with one thread, and MB of text per CPU second.
  subroutine bench_text()
    integer, parameter :: which(2) = [1, 4]
    class(mechanism_t), allocatable :: mech
    type(deck_source_t) :: source
    type(step_table_t) :: table
    type(text_buffer_t) :: out, later
    type(error_t), allocatable :: error
    character(len=:), allocatable :: text
    real(wp) :: t0, t, cells, bytes
    integer :: i, w, c, reps, shown
    character(len=5), parameter :: writer_names(3) = [character(len=5) :: "csv", "json", "table"]
    write (output_unit, '(a,i0,a)') "text output alone, one thread, ", block_rows, &
      " steps with the kinematics columns (cells: rows x CSV columns), per CPU second:"
    do i = 1, size(which)
      if (.not. wanted(which(i))) cycle
      text = scaled_deck(cases(which(i)), block_rows)
      call deck_source_from_text(trim(cases(which(i))%deck), text, source)
      call create_mechanism(trim(cases(which(i))%kind), mech)
      call mech%read_deck(source, error)
      if (allocated(error)) call fail(error)
      table = step_table_t()
      table%kinematics_wanted = .true.
      call mech%solve(table, error)
      if (allocated(error)) call fail(error)
      call table%finish_columns()
      table%kinematics_shown = .true.
      shown = 0
      do c = 1, size(table%columns)
        if (table%columns(c)%csv .and. table%shows(c)) shown = shown + 1
      end do
      do w = 1, size(writer_names)
        reps = 0
        bytes = 0.0_wp
        t0 = clock()
        do
          out%length = 0
          later%length = 0
          select case (w)
          case (1)
            call write_csv(table, out)
          case (2)
            call write_json("bench", table, out)
          case default
            call write_table_rows(mech, table, lang_en, out, later)
          end select
          bytes = bytes + out%length + later%length
          reps = reps + 1
          t = seconds_since(t0)
          if (t > 0.5_wp) exit
        end do
        cells = real(reps, wp) * table%row_count() * shown
        if (w < 3) then
          write (output_unit, '(2x,a8,i5,a,a6,es10.2,a,es10.2,a,f7.1,a)') cases(which(i))%kind, shown, " columns  ", &
            writer_names(w), cells / t, " cells/s", real(reps, wp) * table%row_count() / t, " rows/s", &
            bytes / t / 1.0e6_wp, " MB/s"
        else
          write (output_unit, '(2x,a8,i5,a,a6,a18,es10.2,a,f7.1,a)') cases(which(i))%kind, shown, " columns  ", &
            writer_names(w), "", real(reps, wp) * table%row_count() / t, " rows/s", bytes / t / 1.0e6_wp, " MB/s"
        end if
      end do
      deallocate (mech)
    end do
    flush (output_unit)
  end subroutine bench_text

  !> One case at one step count: one row of the table.
  subroutine bench_one(c, n, path)
    type(bench_case_t), intent(in) :: c
    !> Steps.
    integer, intent(in) :: n
    !> Output file of the end-to-end runs.
    character(*), intent(in) :: path
    character(len=:), allocatable :: text
    integer, parameter :: formats(*) = [format_csv, format_table, format_json, format_npy]
    real(wp) :: kernel_rate, solve_rate, rates(size(formats)), peaks(size(formats))
    integer :: f
    text = scaled_deck(c, n)
    kernel_rate = n / solve_seconds(c, text, .false.)
    solve_rate = n / solve_seconds(c, text, .true.)
    do f = 1, size(formats)
      call reset_peak()
      rates(f) = n / end_to_end_seconds(c, text, formats(f), path)
      peaks(f) = peak_mib()
    end do
    write (output_unit, row_fmt) c%kind, n, kernel_rate, solve_rate, rates, peaks, kernel_rate / limit_rate, &
      solve_rate / limit_rate, rates / limit_rate
    flush (output_unit)
  end subroutine bench_one

  !> Parallel steps: for every wanted kind at the largest step count, the wall time of the
  !> end-to-end CSV and table runs with one thread and with every processor (p), each run
  !> `thread_repeats` times, one thread and p threads in turn (the pairs see about the same
  !> load on a shared machine): the median of each, the speed-up S = the median of the
  !> pairs' ratios t1/tp, and Amdahl's law's projection from the serial fraction it
  !> implies, f = (p/S - 1)/(p - 1): S(k) = 1/(f + (1 - f)/k) for k = 4 and 8 cores, 1/f for
  !> any.
  subroutine bench_threads(path)
    !> Output file of the end-to-end runs.
    character(*), intent(in) :: path
    character(*), parameter :: thread_fmt = '(a8,i9,a7,2f9.3,f8.2,f8.3,3f8.2)'
    integer, parameter :: formats(2) = [format_csv, format_table]
    character(len=5), parameter :: format_names(2) = [character(len=5) :: "csv", "table"]
    !> Runs of each case with 1 and with p threads.
    integer, parameter :: thread_repeats = 5
    character(len=:), allocatable :: text
    real(wp) :: t1(thread_repeats), tp(thread_repeats), ratio(thread_repeats), speedup, serial
    integer :: processors, i, n, f, r
    processors = 1
    !$ processors = omp_get_num_procs()
    if (processors < 2) then
      write (output_unit, '(a)') "parallel steps: one processor (or a build without OpenMP): nothing to compare"
      return
    end if
    n = min(max_steps, step_counts(size(step_counts)))
    write (output_unit, '(a,i0,a,i0,a)') "parallel steps, wall seconds with 1 and ", processors, &
      " threads (the machine's processors; shared machines add the other jobs' time), medians of ", &
      thread_repeats, " runs each in turn; speed-up: the median of their ratios:"
    write (output_unit, '(a)') "    kind    steps format  1 thread  threads speed-up serial  " // &
      "Amdahl: 4 cores 8 cores    any"
    do i = 1, size(cases)
      if (.not. wanted(i)) cycle
      text = scaled_deck(cases(i), n)
      do f = 1, size(formats)
        do r = 1, thread_repeats
          !$ call omp_set_num_threads(1)
          t1(r) = end_to_end_seconds(cases(i), text, formats(f), path, wall=.true.)
          !$ call omp_set_num_threads(processors)
          tp(r) = end_to_end_seconds(cases(i), text, formats(f), path, wall=.true.)
          ratio(r) = t1(r) / tp(r)
        end do
        !$ call omp_set_num_threads(1)
        speedup = median(ratio)
        serial = min(1.0_wp, max(1.0e-3_wp, (processors / speedup - 1.0_wp) / (processors - 1)))
        write (output_unit, thread_fmt) cases(i)%kind, n, format_names(f), median(t1), median(tp), speedup, serial, &
          amdahl(serial, 4), amdahl(serial, 8), 1.0_wp / serial
        flush (output_unit)
      end do
    end do
  end subroutine bench_threads

  !> The median of a few figures (the mean of the middle two of an even count).
  pure real(wp) function median(x)
    !> The figures (at least one).
    real(wp), intent(in) :: x(:)
    real(wp) :: sorted(size(x)), swap
    integer :: i, j, n
    sorted = x
    n = size(x)
    do i = 2, n
      swap = sorted(i)
      j = i - 1
      do while (j >= 1)
        if (sorted(j) <= swap) exit
        sorted(j + 1) = sorted(j)
        j = j - 1
      end do
      sorted(j + 1) = swap
    end do
    median = 0.5_wp * (sorted((n + 1) / 2) + sorted(n / 2 + 1))
  end function median

  !> The general linkage engine against the dyad engine (when no kind or `linkage` is asked
  !> for): the solve alone (as "kernel") per step, processor microseconds, at min(MAX_STEPS,
  !> 10^5) steps, of a class-III &linkage deck against a dyad &assur deck of the same size
  !> (data/class3.nml and data/assur_sixbar.nml: 5 moving links, 7 pairs each), and of the
  !> &linkage twin of the four-bar against the &assur four-bar (3 links); the ratios (the
  !> class-III one's goal: at most 5); then the general engines against the dedicated kernels
  !> per moving link (PR 3207's and the T.FTN six-bar's against their &assur decks, the &assur
  !> four-bar against PR 3207's kernel) and &linkage against &assur on the same slider-crank
  !> and PR 3207 with its flywheel (over one turn).
  subroutine bench_linkage(max_steps)
    !> Largest step count asked for.
    integer, intent(in) :: max_steps
    character(*), parameter :: line_fmt = '(2x,a,t54,f9.2,a,f6.2)'
    character(*), parameter :: link_fmt = '(2x,a,t54,f9.2,f9.3,a,f6.2)'
    character(len=:), allocatable :: arg
    character(len=32) :: count, dphi, turn
    real(wp) :: t_class3, t_sixbar, t_twin, t_fourbar
    real(wp) :: t_pr3207, t_assur_pr3207, t_ftn, t_slider, t_slider_twin, t_fly, t_fly_twin
    logical :: asked
    integer :: i, length, n
    asked = .true.
    do i = 1, command_argument_count()
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: arg)
      call get_command_argument(i, arg)
      if (verify(arg, "0123456789") /= 0 .or. length == 0) asked = .false.
      deallocate (arg)
    end do
    do i = 1, command_argument_count()
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: arg)
      call get_command_argument(i, arg)
      if (arg == "linkage") asked = .true.
      deallocate (arg)
    end do
    if (.not. asked) return
    n = min(max_steps, 100000)
    write (count, '(i0)') n
    write (dphi, '(es24.17)') 360.0_wp / n
    t_class3 = per_step("data/class3.nml", "linkage", "n = "//trim(count)//", drive(1)%step = "//trim(dphi), n)
    t_sixbar = per_step("data/assur_sixbar.nml", "assur", "dphi = "//trim(dphi)//", n = "//trim(count)// &
      ", step_values = "//trim(count)//"*1000", n)
    t_twin = per_step("data/linkage_fourbar.nml", "linkage", "n = "//trim(count)//", drive(1)%step = "//trim(dphi), n)
    t_fourbar = per_step("data/assur_fourbar.nml", "assur", "dphi = "//trim(dphi)//", n = "//trim(count), n)
    write (output_unit, '(a,i0,a)') "general linkages against dyads: CPU microseconds per step of the solve (", n, &
      " steps, as kernel above), ratio:"
    write (output_unit, line_fmt) "class3.nml (&linkage, III(2,3,4,5), 5 links)", t_class3
    write (output_unit, line_fmt) "assur_sixbar.nml (&assur, two dyads, 5 links)", t_sixbar, &
      "   class-III / dyads", t_class3 / t_sixbar
    write (output_unit, line_fmt) "linkage_fourbar.nml (&linkage, II(2,3), 3 links)", t_twin
    write (output_unit, line_fmt) "assur_fourbar.nml (&assur, one dyad, 3 links)", t_fourbar, &
      "   &linkage / &assur", t_twin / t_fourbar
    flush (output_unit)
    ! the general engines against the dedicated kernels, per moving link, and &linkage against
    ! &assur on the same mechanism
    write (turn, '(es24.17)') 360.0_wp / (n - 1)
    t_pr3207 = per_step("data/pr3207.nml", "pr3207", "dphi = "//trim(dphi)//", n = "//trim(count), n)
    t_assur_pr3207 = per_step("data/assur_pr3207.nml", "assur", "dphi = "//trim(dphi)//", n = "//trim(count), n)
    t_ftn = per_step("data/sixbar.nml", "sixbar", "dphi = "//trim(dphi)//", n = "//trim(count)//", f5 = "// &
      trim(count)//"*1000", n)
    t_slider = per_step("data/assur_slider_crank.nml", "assur", "dphi = "//trim(dphi)//", n = "//trim(count), n)
    t_slider_twin = per_step("data/linkage_slider_crank.nml", "linkage", "n = "//trim(count)//", drive(1)%step = "// &
      trim(dphi), n)
    t_fly = per_step("data/assur_pr3207_flywheel.nml", "assur", "dphi = "//trim(turn)//", n = "//trim(count), n)
    t_fly_twin = per_step("data/linkage_pr3207_flywheel.nml", "linkage", "n = "//trim(count)//", drive(1)%step = "// &
      trim(turn), n)
    write (output_unit, '(a,i0,a)') "general engines against the dedicated kernels: CPU microseconds per step and per "// &
      "moving link of the solve (", n, " steps), ratio:"
    write (output_unit, link_fmt) "pr3207.nml (PR 3207's kernel, 5 links)", t_pr3207, t_pr3207 / 5
    write (output_unit, link_fmt) "assur_pr3207.nml (&assur, 5 links)", t_assur_pr3207, t_assur_pr3207 / 5, &
      "   &assur / kernel", t_assur_pr3207 / t_pr3207
    write (output_unit, link_fmt) "assur_fourbar.nml (&assur, 3 links)", t_fourbar, t_fourbar / 3, &
      "   &assur / kernel", (t_fourbar / 3) / (t_pr3207 / 5)
    write (output_unit, link_fmt) "sixbar.nml (T.FTN six-bar's kernel, 5 links)", t_ftn, t_ftn / 5
    write (output_unit, link_fmt) "assur_sixbar.nml (&assur, 5 links)", t_sixbar, t_sixbar / 5, &
      "   &assur / kernel", t_sixbar / t_ftn
    write (output_unit, link_fmt) "linkage_slider_crank.nml (&linkage, 3 links)", t_slider_twin, t_slider_twin / 3, &
      "   &linkage / &assur", t_slider_twin / t_slider
    write (output_unit, link_fmt) "assur_slider_crank.nml (&assur, 3 links)", t_slider, t_slider / 3
    write (output_unit, link_fmt) "linkage_pr3207_flywheel.nml (&linkage, 5 links)", t_fly_twin, t_fly_twin / 5, &
      "   &linkage / &assur", t_fly_twin / t_fly
    write (output_unit, link_fmt) "assur_pr3207_flywheel.nml (&assur, 5 links)", t_fly, t_fly / 5
    flush (output_unit)
  end subroutine bench_linkage

  !> Microseconds per step of the solve of `deck` (kind `kind`) with `extra` appended to its
  !> group, which sets its step count to `n`.
  real(wp) function per_step(deck, kind, extra, n)
    character(*), intent(in) :: deck, kind, extra
    integer, intent(in) :: n
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    character(len=:), allocatable :: text
    call load_deck(deck, source, error)
    if (allocated(error)) error stop "bench: run from the project root (cannot read the bundled decks)"
    text = with_assignments(source, extra)
    per_step = 1.0e6_wp * solve_seconds(bench_case_t(kind, deck), text, .false.) / n
  end function per_step

  !> The machine dynamics stage's cost, processor seconds: for PR 3207 and the generic engine
  !> (when wanted), the deck with its flywheel and the plain deck at the same N steps over one
  !> turn (N = 10^5, or MAX_STEPS if smaller): the solve alone (the steps' kernel with the true
  !> motion and the constant-speed comparison; the cycle itself is solved with the deck) and
  !> the CSV run end to end (deck text to file: the cycle, the steps, 7 more columns), and the
  !> ratio dynamics / plain of each.
  subroutine bench_dynamics(path)
    !> Output file of the end-to-end runs.
    character(*), intent(in) :: path
    character(*), parameter :: dyn_fmt = '(a8,i9,2f9.3,f7.2,2f9.3,f7.2)'
    type(bench_case_t), parameter :: plain(2) = [bench_case_t("pr3207", "data/pr3207.nml"), &
      bench_case_t("assur", "data/assur_pr3207.nml")]
    type(bench_case_t), parameter :: flywheel(2) = [bench_case_t("pr3207", "data/pr3207_flywheel.nml"), &
      bench_case_t("assur", "data/assur_pr3207_flywheel.nml")]
    character(len=:), allocatable :: text_plain, text_dyn
    real(wp) :: s_plain, s_dyn, c_plain, c_dyn
    integer :: i, n
    if (.not. any(wanted .and. (cases%kind == "pr3207" .or. cases%kind == "assur"))) return
    n = min(max_steps, 100000)
    write (output_unit, '(a)') "machine dynamics (steady cycle with its flywheel) against the plain deck, one turn, " // &
      "CPU seconds:"
    write (output_unit, '(a)') "    kind    steps    solve  +dynamics ratio      csv +dynamics ratio"
    do i = 1, size(plain)
      if (.not. any(wanted .and. cases%kind == plain(i)%kind)) cycle
      text_plain = one_turn_deck(plain(i), n)
      text_dyn = one_turn_deck(flywheel(i), n)
      s_plain = solve_seconds(plain(i), text_plain, .false.)
      s_dyn = solve_seconds(flywheel(i), text_dyn, .false.)
      c_plain = end_to_end_seconds(plain(i), text_plain, format_csv, path)
      c_dyn = end_to_end_seconds(flywheel(i), text_dyn, format_csv, path)
      write (output_unit, dyn_fmt) plain(i)%kind, n, s_plain, s_dyn, s_dyn / s_plain, c_plain, c_dyn, c_dyn / c_plain
      flush (output_unit)
    end do
  end subroutine bench_dynamics

  !> A bundled deck at `n` steps over exactly one turn (dphi = 360/(n - 1); a steady cycle
  !> needs it), as the text of a deck.
  function one_turn_deck(c, n) result(text)
    type(bench_case_t), intent(in) :: c
    integer, intent(in) :: n
    character(len=:), allocatable :: text
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    character(len=32) :: dphi, count
    call load_deck(trim(c%deck), source, error)
    if (allocated(error)) error stop "bench: run from the project root (cannot read the bundled decks)"
    write (dphi, '(es24.17)') 360.0_wp / (n - 1)
    write (count, '(i0)') n
    text = with_assignments(source, "dphi = "//trim(dphi)//", n = "//trim(count))
  end function one_turn_deck

  !> The text of a deck with `extra` assignments added to its group, before the closing '/'
  !> (namelist: the last value given wins).
  function with_assignments(source, extra) result(text)
    type(deck_source_t), intent(in) :: source
    character(*), intent(in) :: extra
    character(len=:), allocatable :: text
    integer :: k, last
    last = deck_line_count(source)
    do k = deck_line_count(source), 1, -1
      if (adjustl(deck_line(source, k)) == "/") then
        last = k
        exit
      end if
    end do
    text = ""
    do k = 1, last - 1
      text = text//trim(deck_line(source, k))//new_line("a")
    end do
    text = text//"  "//extra//new_line("a")//"/"//new_line("a")
  end function with_assignments

  !> Amdahl's law: the speed-up on `cores` cores of a run whose serial fraction is `serial`.
  pure real(wp) function amdahl(serial, cores)
    !> Serial fraction of the one-thread time, 0..1.
    real(wp), intent(in) :: serial
    !> Cores.
    integer, intent(in) :: cores
    amdahl = 1.0_wp / (serial + (1.0_wp - serial) / cores)
  end function amdahl

  !> The bundled deck with its step count set to `n` (namelist: the last value given wins).
  function scaled_deck(c, n) result(text)
    type(bench_case_t), intent(in) :: c
    integer, intent(in) :: n
    character(len=:), allocatable :: text
    type(deck_source_t) :: source
    type(error_t), allocatable :: error
    character(len=:), allocatable :: extra
    character(len=32) :: dphi, count
    call load_deck(trim(c%deck), source, error)
    if (allocated(error)) error stop "bench: run from the project root (cannot read the bundled decks)"
    write (dphi, '(es24.17)') 360.0_wp / n
    write (count, '(i0)') n
    select case (trim(c%kind))
    case ("pr3207")
      extra = "dphi = "//trim(dphi)//", n = "//trim(count)
    case ("pr3050")
      write (dphi, '(es24.17)') 45.0_wp / (n - 1)
      extra = "dphi3 = "//trim(dphi)//", omega3 = "//trim(count)//"*0.4, eps3 = "//trim(count)//"*0.1"
    case ("sixbar")
      extra = "dphi = "//trim(dphi)//", n = "//trim(count)//", f5 = "//trim(count)//"*1000"
    case ("assur")
      extra = "dphi = "//trim(dphi)//", n = "//trim(count)//", step_values = "//trim(count)//"*1000"
    case default
      extra = "dphi = "//trim(dphi)//", n = "//trim(count)//", ds_dphi = "//trim(count)//"*0.01"
    end select
    text = with_assignments(source, extra)
  end function scaled_deck

  !> Seconds of the solve alone (kernel and step table, in the run's blocks of steps) of a
  !> deck read beforehand: with the kinematics columns (`kinematics`; as --kinematics,
  !> --frame link and SVG runs) or without them (as a plain run: the kernel and its result
  !> columns).
  real(wp) function solve_seconds(c, text, kinematics)
    type(bench_case_t), intent(in) :: c
    character(*), intent(in) :: text
    logical, intent(in) :: kinematics
    class(mechanism_t), allocatable :: mech
    type(deck_source_t) :: source
    type(step_table_t) :: table
    type(error_t), allocatable :: error
    real(wp) :: t0
    call deck_source_from_text(trim(c%deck), text, source)
    call create_mechanism(trim(c%kind), mech)
    call mech%read_deck(source, error)
    if (allocated(error)) call fail(error)
    table%kinematics_wanted = kinematics
    t0 = clock()
    ! in the run's blocks of steps, as the run pipeline solves them
    table%block_first = 1
    table%block_last = block_rows
    do
      call mech%solve(table, error)
      if (allocated(error)) call fail(error)
      call table%finish_columns()
      if (table%last_block()) exit
      table%block_first = table%block_last + 1
      table%block_last = table%block_last + block_rows
    end do
    solve_seconds = seconds_since(t0)
  end function solve_seconds

  !> Seconds from the deck's text to the closed output file, as `kinetostat DECK -o FILE`:
  !> processor seconds, or wall seconds with `wall`.
  real(wp) function end_to_end_seconds(c, text, format, path, wall)
    type(bench_case_t), intent(in) :: c
    character(*), intent(in) :: text
    integer, intent(in) :: format
    character(*), intent(in) :: path
    !> Wall-clock seconds instead of processor seconds.
    logical, intent(in), optional :: wall
    logical :: by_wall
    class(mechanism_t), allocatable :: mech
    character(len=:), allocatable :: group
    type(deck_source_t) :: source
    type(step_table_t) :: table
    type(text_buffer_t) :: out
    type(spool_t) :: spool
    type(run_options_t) :: options
    type(error_t), allocatable :: error
    real(wp) :: t0
    options%format = format
    by_wall = .false.
    if (present(wall)) by_wall = wall
    if (by_wall) then
      t0 = wall_clock()
    else
      t0 = clock()
    end if
    call deck_source_from_text(trim(c%deck), text, source)
    call read_group_name(source, group, error)
    if (allocated(error)) call fail(error)
    call create_mechanism(group, mech)
    call spool%aim(path)
    call run_mechanism(mech, group, source, options, table, out, error, spool)
    if (allocated(error)) call fail(error)
    call spool%commit(out, error)
    if (allocated(error)) call fail(error)
    if (by_wall) then
      end_to_end_seconds = max(wall_clock() - t0, 1.0e-6_wp)
    else
      end_to_end_seconds = seconds_since(t0)
    end if
  end function end_to_end_seconds

  !> Wall-clock time, s (from an arbitrary origin).
  real(wp) function wall_clock()
    integer(int64) :: count, rate
    call system_clock(count, rate)
    wall_clock = real(count, wp) / real(rate, wp)
  end function wall_clock

  subroutine fail(error)
    type(error_t), intent(in) :: error
    write (output_unit, '(a)') "bench: "//error%message
    error stop 1
  end subroutine fail

  !> Processor time of the process so far, s (all threads; the machine may be shared, so
  !> processor time, not wall time, measures the program).
  real(wp) function clock()
    call cpu_time(clock)
  end function clock

  !> Processor seconds since `t0` (at least 1 us).
  real(wp) function seconds_since(t0)
    !> Start, from clock().
    real(wp), intent(in) :: t0
    seconds_since = max(clock() - t0, 1.0e-6_wp)
  end function seconds_since

  !> Reset the peak resident set size of this process: free heap memory back to the system
  !> (glibc malloc_trim), then "5" into /proc/self/clear_refs (Linux).
  subroutine reset_peak()
    integer :: unit, ios
    if (malloc_trim(0_c_size_t) < 0) return
    open (newunit=unit, file="/proc/self/clear_refs", action='write', iostat=ios)
    if (ios /= 0) return
    write (unit, '(a)', iostat=ios) "5"
    if (ios /= 0) write (output_unit, '(a)') "bench: cannot reset the peak memory; the peaks are since the start"
    close (unit)
  end subroutine reset_peak

  !> Peak resident set size since the last reset, MiB (VmHWM of /proc/self/status; 0 if unknown).
  real(wp) function peak_mib()
    character(len=256) :: line
    integer :: unit, ios
    integer(int64) :: kib
    peak_mib = 0.0_wp
    open (newunit=unit, file="/proc/self/status", action='read', iostat=ios)
    if (ios /= 0) return
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:6) == "VmHWM:") then
        read (line(7:), *, iostat=ios) kib
        if (ios == 0) peak_mib = real(kib, wp) / 1024.0_wp
        exit
      end if
    end do
    close (unit)
  end function peak_mib

end program bench
