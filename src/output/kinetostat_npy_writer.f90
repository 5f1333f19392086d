!> NumPy writer (--format npy): the columns of the CSV as one NumPy `.npy` file, a structured
!> array of one record per row with a little-endian float64 field per column, named as in
!> the CSV header, that `numpy.load` reads (and `pandas.DataFrame(numpy.load(F))` makes a
!> data frame of). The values are the computed ones (not the CSV's 13 digits); flags and
!> counts are 0.0/1.0 and whole numbers, and a cell the CSV leaves empty (no value: a jammed
!> cam follower's forces) is NaN, the one place a NaN is written. The header (format version
!> 1.0 for ASCII names, 2.0 when it is longer than 65535 bytes, 3.0 for names with UTF-8
!> characters) holds the number of rows, which the run knows from its first block, so the
!> rows are written block by block as the CSV's are and memory stays flat.
!> Format: https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html
module kinetostat_npy_writer
  use, intrinsic :: iso_fortran_env, only: int32, int64
  use, intrinsic :: iso_c_binding, only: c_f_pointer, c_loc
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str
  use kinetostat_escape, only: python_string
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: write_npy, npy_header, put_npy_values

  !> Bytes of one value (float64).
  integer, parameter :: value_bytes = 8
  !> The header (magic, version, length, dictionary) is padded to a multiple of this.
  integer, parameter :: header_alignment = 64
  !> Largest dictionary of a version 1.0 header (its length is an unsigned 16-bit number).
  integer, parameter :: max_v1_header = 65535

contains

  !> The rows of a step table as an npy file: with the first block the header (the CSV's
  !> columns, the run's row count), then the block's rows. `error` when the rows of the run
  !> do not come to the count in the header (a mechanism that gave another number of rows
  !> than it announced: a bug).
  subroutine write_npy(table, out, error)
    !> Finite results.
    type(step_table_t), intent(in) :: table
    !> Where the bytes go (its reserved bytes are written through a float64 view).
    type(text_buffer_t), intent(inout), target :: out
    !> The rows written differ from the header's count.
    type(error_t), allocatable, intent(out) :: error
    integer, allocatable :: columns(:)
    logical, allocatable :: voidable(:)
    real(wp), pointer, contiguous :: records(:, :)
    real(wp) :: nan
    integer :: c, k, n, longest
    allocate (columns(0))
    longest = 1
    do c = 1, size(table%columns)
      if (.not. (table%columns(c)%csv .and. table%shows(c))) cycle
      columns = [columns, c]
      longest = max(longest, len(table%columns(c)%name))
    end do
    n = size(columns)
    if (table%first_block()) call out%append(table_header(table, columns, longest))
    allocate (voidable(n))
    do c = 1, n
      voidable(c) = table%columns(columns(c))%voidable
    end do
    nan = ieee_value(1.0_wp, ieee_quiet_nan)
    call out%reserve(table%row_count() * n * value_bytes)
    if (.not. host_little_endian()) then
      do k = 1, table%row_count()
        call put_npy_values(out, merge(nan, table%rows(columns, k) + 0.0_wp, voidable .and. table%is_void(k)))
      end do
    else if (table%row_count() > 0 .and. n > 0) then
      ! the records straight into the buffer (the machine's byte order is the file's): its
      ! reserved bytes seen as the block's records of float64 values
      call c_f_pointer(c_loc(out%data(out%length + 1:out%length + 1)), records, [n, table%row_count()])
      call put_records(table%rows(:, 1:table%row_count()), size(table%rows, 1), table%row_count(), columns, records)
      if (allocated(table%void_flags)) then
        do k = 1, table%row_count()
          if (table%is_void(k)) records(:, k) = merge(nan, records(:, k), voidable)
        end do
      end if
      out%length = out%length + n * table%row_count() * value_bytes
    end if
    if (table%last_block() .and. table%row_offset + table%row_count() /= table%total_rows) then
      call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": --format npy: the run gave "// &
        int_str(table%row_offset + table%row_count())//" rows, not the "//int_str(table%total_rows)// &
        " its first block announced (a bug: please report it)")
    end if
  end subroutine write_npy

  !> The header of a step table's npy file: its `columns`, the run's row count.
  pure function table_header(table, columns, longest) result(text)
    type(step_table_t), intent(in) :: table
    !> The columns written.
    integer, intent(in) :: columns(:)
    !> Length of the longest of their names.
    integer, intent(in) :: longest
    character(len=:), allocatable :: text
    character(len=longest) :: names(size(columns))
    integer :: lengths(size(columns)), c
    do c = 1, size(columns)
      names(c) = table%columns(columns(c))%name
      lengths(c) = len(table%columns(columns(c))%name)
    end do
    text = npy_header(names, lengths, table%total_rows)
  end function table_header

  !> The header of an npy file of `rows` records of float64 fields named `names` (each of
  !> length lengths(i); trailing blanks of `names` beyond it are not part of the name).
  pure function npy_header(names, lengths, rows) result(text)
    !> Field names (blank-padded).
    character(*), intent(in) :: names(:)
    !> Length of each name.
    integer, intent(in) :: lengths(:)
    !> Number of records.
    integer, intent(in) :: rows
    character(len=:), allocatable :: text
    character(len=:), allocatable :: dict
    integer :: i, total, size_bytes, major
    logical :: ascii
    ascii = .true.
    dict = "{'descr': ["
    do i = 1, size(names)
      if (i > 1) dict = dict//", "
      dict = dict//"("//python_string(names(i)(1:lengths(i)))//", '<f8')"
      ascii = ascii .and. is_ascii(names(i)(1:lengths(i)))
    end do
    dict = dict//"], 'fortran_order': False, 'shape': ("//int_str(rows)//",), }"
    major = 1
    size_bytes = 2
    if (.not. ascii) then
      major = 3
      size_bytes = 4
    else if (len(dict) + header_alignment > max_v1_header) then
      major = 2
      size_bytes = 4
    end if
    ! padded with blanks and ended by a newline to a multiple of 64 bytes in all
    total = 6 + 2 + size_bytes + len(dict) + 1
    total = (total + header_alignment - 1) / header_alignment * header_alignment
    dict = dict//repeat(" ", total - (6 + 2 + size_bytes + len(dict) + 1))//achar(10)
    text = char(147)//"NUMPY"//char(major)//char(0)//little_endian(len(dict), size_bytes)//dict
  end function npy_header

  !> Append one record (the values as little-endian float64).
  pure subroutine put_npy_values(out, values)
    !> Where the bytes go.
    type(text_buffer_t), intent(inout) :: out
    !> The record's values.
    real(wp), intent(in) :: values(:)
    character(len=value_bytes) :: bytes
    integer :: i, n
    logical :: swap
    swap = .not. host_little_endian()
    call out%reserve(size(values) * value_bytes)
    n = out%length
    do i = 1, size(values)
      bytes = transfer(values(i), bytes)
      if (swap) bytes = reversed(bytes)
      out%data(n + 1:n + value_bytes) = bytes
      n = n + value_bytes
    end do
    out%length = n
  end subroutine put_npy_values

  !> The records of rows(columns, :), minus zero as zero (+0.0).
  pure subroutine put_records(rows, n_values, n_rows, columns, records)
    !> Values a row (the leading extent of `rows`).
    integer, intent(in) :: n_values
    !> Rows.
    integer, intent(in) :: n_rows
    !> The rows' values, a row a column.
    real(wp), intent(in) :: rows(n_values, n_rows)
    !> The columns written, in order.
    integer, intent(in) :: columns(:)
    !> The records, one a column.
    real(wp), intent(out) :: records(size(columns), n_rows)
    integer :: i, k
    if (size(columns) == n_values) then
      if (all(columns == [(i, i = 1, n_values)])) then
        records = rows + 0.0_wp              ! every column, in order
        return
      end if
    end if
    do k = 1, n_rows
      do i = 1, size(columns)
        records(i, k) = rows(columns(i), k) + 0.0_wp
      end do
    end do
  end subroutine put_records

  !> Whether this machine stores numbers least significant byte first.
  pure logical function host_little_endian()
    host_little_endian = transfer(1_int32, "abcd") == achar(1)//achar(0)//achar(0)//achar(0)
  end function host_little_endian

  !> Whether every byte of `s` is ASCII (below 128).
  pure logical function is_ascii(s)
    character(*), intent(in) :: s
    integer :: i
    is_ascii = .true.
    do i = 1, len(s)
      if (iachar(s(i:i)) >= 128) is_ascii = .false.
    end do
  end function is_ascii

  !> The bytes of `s` in reverse order.
  pure function reversed(s) result(t)
    character(*), intent(in) :: s
    character(len=len(s)) :: t
    integer :: i
    do i = 1, len(s)
      t(i:i) = s(len(s) - i + 1:len(s) - i + 1)
    end do
  end function reversed

  !> `n` as an unsigned little-endian number of `bytes` bytes.
  pure function little_endian(n, bytes) result(text)
    integer, intent(in) :: n, bytes
    character(len=bytes) :: text
    integer(int64) :: rest
    integer :: i
    rest = n
    do i = 1, bytes
      text(i:i) = char(int(mod(rest, 256_int64)))
      rest = rest / 256_int64
    end do
  end function little_endian

end module kinetostat_npy_writer
