!> The friction of an `&linkage` deck in the step table, as `&assur` has it (docs/friction.md):
!> the columns after the drives' efforts (<effort>_0 without friction, P_loss_<pair> for every
!> pair with friction, P_loss, eta_defined, eta), the works over the run and the summary, the
!> INPUT DATA lines (the friction block of RESULTS: kinetostat_friction_block).
module kinetostat_linkage_friction_table
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_text, only: upper
  use kinetostat_noise, only: noise_rel
  use kinetostat_vec2, only: largest_magnitude
  use kinetostat_run_tally, only: trapezoid_t
  use kinetostat_step_table, only: step_table_t, column, col_moment, col_component, col_other, col_flag, col_ratio
  use kinetostat_labels, only: lang_ru
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_linkage, only: linkage_t, linkage_step_t, pair_r
  use kinetostat_linkage_friction, only: linkage_friction_t
  use kinetostat_linkage_deck, only: linkage_deck_t, linkage_drive_values
  use kinetostat_friction_block, only: friction_efficiency, friction_step_values
  implicit none
  private
  public :: add_friction_columns, friction_values, friction_integrals, friction_summary, echo_friction


contains

  !> The friction columns: `effort`_0 (the first drive's effort without friction: N*m or N),
  !> P_loss_<force column> (W) for every pair with friction, P_loss, eta_defined, eta.
  pure subroutine add_friction_columns(deck, effort, force_names, table)
    type(linkage_deck_t), intent(in) :: deck
    !> The first drive's effort column (M1, F_drive1).
    character(*), intent(in) :: effort
    !> Every pair's force column (F21, ...).
    character(len=*), intent(in) :: force_names(:)
    type(step_table_t), intent(inout) :: table
    integer :: k
    if (deck%mech%pairs(deck%mech%drives(1)%pair)%kind == pair_r) then
      call table%declare_columns([column(effort//"_0", "N*m", col_moment, heading=upper(effort)//"_0")])
    else
      call table%declare_columns([column(effort//"_0", "N", col_component, heading=upper(effort)//"_0")])
    end if
    do k = 1, size(force_names)
      if (deck%friction_f(k) > 0.0_wp) call table%declare_columns([column("P_loss_"//trim(force_names(k)), "W", &
                                                                         col_other, heading="P_"//trim(force_names(k)))])
    end do
    call table%declare_columns([column("P_loss", "W", col_other, heading="P_LOSS"), column("eta_defined", "", col_flag), &
                                column("eta", "", col_ratio, heading="ETA")])
  end subroutine add_friction_columns

  !> The friction values of a step in the order of add_friction_columns. eta = 1 - R/D (R the
  !> loss, D the drives' virtual power, both per unit of the reference rate) where D > 0;
  !> elsewhere eta_defined = 0 and eta = 0.
  pure function friction_values(deck, s, fr) result(v)
    type(linkage_deck_t), intent(in) :: deck
    !> The step with friction.
    type(linkage_step_t), intent(in) :: s
    type(linkage_friction_t), intent(in) :: fr
    real(wp), allocatable :: v(:)
    real(wp) :: floor
    floor = noise_rel * largest_magnitude(s%f)
    if (deck%mech%pairs(deck%mech%drives(1)%pair)%kind == pair_r) floor = floor * deck%mech%size
    v = friction_step_values(merge(0.0_wp, fr%effort0(1), abs(fr%effort0(1)) <= floor), &
                             pack(fr%loss(:size(deck%friction_f)), deck%friction_f > 0.0_wp), fr%p_loss, &
                             fr%rate_total, fr%driver_rate)
  end function friction_values

  !> The works of steps step1 .. step1 + size(frs) - 1 as points to integrate over the first
  !> drive's value (rad or m): [the drives' virtual power, the loss], per unit of the
  !> reference rate: fed in row order they give the work of the drives and the work lost, J.
  pure function friction_integrals(deck, frs, step1) result(works)
    type(linkage_deck_t), intent(in) :: deck
    type(linkage_friction_t), intent(in) :: frs(:)
    integer, intent(in) :: step1
    type(trapezoid_t) :: works(2)
    real(wp) :: dq(size(deck%mech%drives)), dv(size(deck%mech%drives)), da(size(deck%mech%drives))
    integer :: i
    do i = 1, 2
      works(i)%unit = 1.0_wp
      allocate (works(i)%x(size(frs)), works(i)%y(size(frs)))
    end do
    do i = 1, size(frs)
      call linkage_drive_values(deck, step1 - 1 + i, dq, dv, da)
      works(1)%x(i) = dq(1)
      works(1)%y(i) = frs(i)%driver_rate
      works(2)%y(i) = frs(i)%rate_total
    end do
    works(2)%x = works(1)%x
  end function friction_integrals

  !> The summary of a run with friction: the works, the efficiency and what it means.
  pure subroutine friction_summary(deck, a_driver, a_loss, table)
    type(linkage_deck_t), intent(in) :: deck
    !> Work of the drives and work lost to friction over the run, J.
    real(wp), intent(in) :: a_driver, a_loss
    type(step_table_t), intent(inout) :: table
    real(wp) :: span, q1(size(deck%mech%drives)), qn(size(deck%mech%drives)), dv(size(deck%mech%drives)), &
      da(size(deck%mech%drives))
    logical :: turning
    call linkage_drive_values(deck, 1, q1, dv, da)
    call linkage_drive_values(deck, deck%n, qn, dv, da)
    turning = deck%mech%pairs(deck%mech%drives(1)%pair)%kind == pair_r
    span = abs(qn(1) - q1(1))
    table%summary_heading = "WORK AND EFFICIENCY WITH FRICTION"
    if (turning) then
      call table%summary_real("RUN SPAN", span / deg_to_rad, "deg")
    else
      call table%summary_real("RUN SPAN", span, "m")
    end if
    if (turning) then
      call friction_efficiency(a_driver, a_loss, span / deg_to_rad, table)
    else
      call friction_efficiency(a_driver, a_loss, 0.0_wp, table)
    end if
  end subroutine friction_summary

  !> INPUT DATA lines of pair k's friction: F, and R (turning) or CONTACT_SPAN (sliding).
  pure subroutine echo_friction(deck, k, table)
    type(linkage_deck_t), intent(in) :: deck
    integer, intent(in) :: k
    type(step_table_t), intent(inout) :: table
    if (.not. deck%friction_f(k) > 0.0_wp) return
    call table%echo_real("  F", deck%friction_f(k), "")
    if (deck%mech%pairs(k)%kind == pair_r) then
      call table%echo_real("  R", deck%friction_r(k), "m")
    else
      call table%echo_real("  CONTACT_SPAN", deck%friction_span(k), "m")
    end if
  end subroutine echo_friction

end module kinetostat_linkage_friction_table
