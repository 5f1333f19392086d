!> The shaking stage on a hand-made step table: one body and one frame pair with values whose
!> shaking force, moment and frame total are worked by hand; the components' frame turned;
!> a prismatic pair's moment; a second block keeps its columns; a missing column is an error.
module test_shaking
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_step_table, only: step_table_t, col_other, col_component, col_moment, col_length
  use kinetostat_shaking, only: add_shaking
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_shaking_tests

contains

  !> All tests of this suite.
  subroutine run_shaking_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_by_hand(t)
    call test_missing_column(t)
  end subroutine run_shaking_tests

  !> A table of one row: S1 at (0.1, 0.2) m with a = (-3, 4) m/s^2, eps1 = 5 rad/s^2; the
  !> frame pair F10 = (1, 2) N in axes turned by 90 deg at P = (0.3, -0.1) m with a pair
  !> moment F10M = 0.4 N*m; M1 = 7 N*m. With m = 2 kg, J = 0.5 kg*m^2:
  !> F_shake = -m a = (6, -8) N, |F| = 10 N at 306.8699 deg; M_shake = -m (r x a) - J eps =
  !> -2 (0.4 + 0.6) - 2.5 = -4.5 N*m; the pair force in the table's axes (-2, 1) N, so
  !> F_frame = (2, -1) N and M_frame = -(0.3*1 - (-0.1)(-2)) - 0.4 - 7 = -7.5 N*m.
  subroutine test_by_hand(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    type(mass_model_t) :: model
    type(error_t), allocatable :: error
    real(wp), parameter :: expected(8) = [10.0_wp, 306.86989764584402_wp, 6.0_wp, -8.0_wp, -4.5_wp, &
      2.0_wp, -1.0_wp, -7.5_wp]
    character(len=9), parameter :: names(8) = [character(len=9) :: "F_shake", "F_shakeG", "F_shake_x", &
      "F_shake_y", "M_shake", "F_frame_x", "F_frame_y", "M_frame"]
    integer :: pass, i, columns
    call hand_table(table)
    call model%add("1", "S1", 2.0_wp, 0.5_wp)
    call model%add_frame_pair("F10", "P", "F10M")
    model%drive = "M1"
    do pass = 1, 2
      call add_shaking(table, model, error)
      call check_true(t, "shaking: hand table runs", .not. allocated(error), "unexpected error")
      if (allocated(error)) return
      if (pass == 1) columns = size(table%columns)
      do i = 1, size(names)
        call check_close(t, "shaking: hand table, block "//achar(48 + pass)//", "//trim(names(i)), expected(i), &
          table%rows(table%column_index(trim(names(i))), 1), 1.0e-14_wp, 1.0e-14_wp)
      end do
    end do
    call check_true(t, "shaking: a later block adds no columns", size(table%columns) == columns, "columns grew")
    ! a steady cycle's flywheel and rotor on the input shaft: their couple -(J_fw + j_rotor) eps1
    ! = -(3 + 1)*5 joins M_shake (M_frame comes from the reactions)
    call hand_table(table)
    table%dynamics%present = .true.
    table%dynamics%j_flywheel = 3.0_wp
    table%dynamics%j_rotor = 1.0_wp
    call add_shaking(table, model, error)
    call check_true(t, "shaking: hand table with a flywheel runs", .not. allocated(error), "unexpected error")
    if (allocated(error)) return
    call check_close(t, "shaking: M_shake with the flywheel and rotor couple", -24.5_wp, &
      table%rows(table%column_index("M_shake"), 1), 1.0e-14_wp, 1.0e-14_wp)
  end subroutine test_by_hand

  !> A model naming a centre of mass the table lacks: an error naming the column.
  subroutine test_missing_column(t)
    type(test_counts_t), intent(inout) :: t
    type(step_table_t) :: table
    type(mass_model_t) :: model
    type(error_t), allocatable :: error
    call hand_table(table)
    call model%add("2", "S2", 1.0_wp, 0.0_wp)
    call add_shaking(table, model, error)
    call check_true(t, "shaking: a missing column is an error naming it", allocated(error), "no error")
    if (allocated(error)) call check_true(t, "shaking: the error names x_S2", index(error%message, "x_S2") > 0, &
      error%message)
  end subroutine test_missing_column

  !> The one-row table of test_by_hand.
  subroutine hand_table(table)
    type(step_table_t), intent(out) :: table
    table%deck = "hand.nml"
    table%mechanism = "hand"
    call table%set_columns([character(len=5) :: "phi1", "M1", "x_S1", "y_S1", "ax_S1", "ay_S1", "eps1", "F10_x", &
      "F10_y", "x_P", "y_P", "F10M"], [character(len=7) :: "deg", "N*m", "m", "m", "m/s^2", "m/s^2", "rad/s^2", &
      "N", "N", "m", "m", "N*m"], [col_other, col_moment, col_length, col_length, col_other, col_other, col_other, &
      col_component, col_component, col_length, col_length, col_moment])
    table%columns(8:9)%frame_angle = 90.0_wp
    call table%allocate_rows(1)
    table%rows(:, 1) = [0.0_wp, 7.0_wp, 0.1_wp, 0.2_wp, -3.0_wp, 4.0_wp, 5.0_wp, 1.0_wp, 2.0_wp, 0.3_wp, -0.1_wp, &
      0.4_wp]
  end subroutine hand_table

end module test_shaking
