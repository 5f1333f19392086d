!> What `kinetostat balance` does alike for `&assur` and `&linkage` decks (their readers keep
!> what they know of their links: the sample poses, the pivots, where a counterweight sits):
!> the methods' codes and names, the full static balance's least-squares fit of the pivoted
!> links' first moments (Berkof-Lowen's linearly independent vectors) with its refusals, and
!> the report's and the deck's words (the partial method's harmonics, a counterweight's note,
!> its assignments and the line of the changed mass, moment of inertia and centre of mass).
module kinetostat_counterweights
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str
  use kinetostat_format, only: full_number, short_number
  use kinetostat_labels, only: lang_ru, unit_symbol, in_language
  use kinetostat_least_squares, only: least_squares
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_vec2, only: rotate
  use kinetostat_override, only: override_t, append_override
  implicit none
  private
  public :: balance_full, balance_crank, balance_partial, balance_method_names
  public :: fit_full_balance, report_full_balance, report_partial_balance
  public :: counterweight_note, add_counterweight_assignments

  !> --method full: the shaking force vanishes (Berkof-Lowen).
  integer, parameter :: balance_full = 1
  !> --method crank: the crank's own centre of mass on its pivot.
  integer, parameter :: balance_crank = 2
  !> --method partial: a slider-crank's rotating mass and a fraction of its reciprocating mass.
  integer, parameter :: balance_partial = 3
  !> The method names, in the order of their codes.
  character(*), parameter :: balance_method_names(*) = [character(len=7) :: "full", "crank", "partial"]
  !> Full balance exists when the least-squares residual of the first moment is at most this
  !> times its unbalanced variation.
  real(wp), parameter :: balance_rel = 1.0e-9_wp

contains

  !> Full static balance's fit: the first moments w_j (link axes, about the pivot) of the
  !> pivoted links j and the constant C with sum_j R(theta_j) w_j - C = -(the first moment of
  !> the rest) at every sample, in the least-squares sense. `x` is (w_1, ..., w_n, C), and
  !> w_j goes into `w_new` with `carries` set; `x` is unallocated when the total centre of
  !> mass does not move (reported: nothing to balance). Exit 3 when the fit is not determined
  !> or leaves a residual (full balance impossible).
  pure subroutine fit_full_balance(moment, theta, mass, own, pivoted, lang, report, w_new, carries, x, error)
    !> The total first moment of mass at every sample (2, samples), kg*m.
    real(wp), intent(in) :: moment(:, :)
    !> Each link's angle at every sample (links, samples), rad.
    real(wp), intent(in) :: theta(:, :)
    !> Each link's mass, kg, and its centre of mass about its pivot (or origin) in the link's
    !> axes (2, links), m.
    real(wp), intent(in) :: mass(:), own(:, :)
    !> The links pivoted on the frame.
    integer, intent(in) :: pivoted(:)
    !> Language of the report.
    integer, intent(in) :: lang
    type(text_buffer_t), intent(inout) :: report
    !> The new first moments of the links (2, links), kg*m, and which links carry one.
    real(wp), intent(inout) :: w_new(:, :)
    logical, intent(inout) :: carries(:)
    real(wp), allocatable, intent(out) :: x(:)
    type(error_t), allocatable, intent(out) :: error
    real(wp), allocatable :: a(:, :), b(:)
    real(wp) :: mean(2), unbalanced, residual, r(2)
    integer :: ns, np, k, j, nu, i
    ns = size(moment, 2)
    np = size(pivoted)
    mean = sum(moment, dim=2) / real(ns, wp)
    unbalanced = 0.0_wp
    do k = 1, ns
      unbalanced = max(unbalanced, norm2(moment(:, k) - mean))
    end do
    if (.not. unbalanced > 0.0_wp) then
      call report%put(in_language("full balance: the total centre of mass does not move (nothing to balance)", &
        "полное статическое уравновешивание: общий центр масс "// &
        "неподвижен (уравновешивать нечего)", lang))
      return
    end if
    ! unknowns: w of each pivoted link (x, y), then the constant C (x, y)
    nu = 2 * np + 2
    allocate (a(2 * ns, nu), b(2 * ns), x(nu))
    do k = 1, ns
      b(2 * k - 1:2 * k) = -moment(:, k)
      do j = 1, np
        i = pivoted(j)
        b(2 * k - 1:2 * k) = b(2 * k - 1:2 * k) + mass(i) * rotate(own(:, i), theta(i, k))
        a(2 * k - 1:2 * k, 2 * j - 1) = rotate([1.0_wp, 0.0_wp], theta(i, k))
        a(2 * k - 1:2 * k, 2 * j) = rotate([0.0_wp, 1.0_wp], theta(i, k))
      end do
      a(2 * k - 1:2 * k, nu - 1) = [-1.0_wp, 0.0_wp]
      a(2 * k - 1:2 * k, nu) = [0.0_wp, -1.0_wp]
    end do
    call least_squares(a, b, x, error)
    if (allocated(error)) then
      call fatal_error(error, exit_geometry, "full balance: the counterweights are not determined (the links "// &
        "pivoted on the frame move together); balance the crank alone (--method crank)")
      return
    end if
    residual = 0.0_wp
    do k = 1, ns
      r = -moment(:, k)
      do j = 1, np
        i = pivoted(j)
        r = r + rotate(mass(i) * own(:, i) - x(2 * j - 1:2 * j), theta(i, k))
      end do
      residual = max(residual, norm2(r + x(nu - 1:nu)))
    end do
    if (residual > balance_rel * unbalanced) then
      call fatal_error(error, exit_geometry, "full balance is impossible: counterweights on the links pivoted on "// &
        "the frame leave "//short_number(residual / unbalanced * 100.0_wp)//" % of the centre of mass's travel "// &
        "(a link whose origin moves, such as a slider on the frame, cannot be balanced by them); "// &
        "use --method partial [--fraction F] (a slider-crank) or --method crank")
      return
    end if
    do j = 1, np
      w_new(:, pivoted(j)) = x(2 * j - 1:2 * j)
      carries(pivoted(j)) = .true.
    end do
  end subroutine fit_full_balance

  !> The report's line of a full balance: how many links carry counterweights and where the
  !> total centre of mass stays.
  pure subroutine report_full_balance(report, lang, links, centre)
    type(text_buffer_t), intent(inout) :: report
    integer, intent(in) :: lang
    !> Links with counterweights.
    integer, intent(in) :: links
    !> The total centre of mass after balancing, m.
    real(wp), intent(in) :: centre(2)
    call report%put(in_language("full balance (linearly independent vectors): counterweights on the "// &
      int_str(links)//" links pivoted on the frame; the total centre of mass stays at (", &
      "полное статическое уравновешивание (метод линейно "// &
      "независимых векторов): противовесы на "//int_str(links)//" звеньях, "// &
      "вращающихся вокруг неподвижных осей; общий центр масс "// &
      "неподвижен в точке (", &
      lang)//short_number(centre(1))//", "//short_number(centre(2))//") "//unit_symbol("m", lang))
  end subroutine report_full_balance

  !> The report's lines of a slider-crank's partial balance: the masses balanced, and the
  !> primary and secondary components of the shaking force before and after.
  pure subroutine report_partial_balance(report, lang, which_en, which_ru, m_rot, m_rec, fraction, share, r, l, &
                                         omega)
    type(text_buffer_t), intent(inout) :: report
    integer, intent(in) :: lang
    !> Which slider-crank, after "the slider-crank" (" (dyad 1)", or empty), in English and in
    !> Russian.
    character(*), intent(in) :: which_en, which_ru
    !> The rotating and the reciprocating mass, kg; the fraction of the latter balanced.
    real(wp), intent(in) :: m_rot, m_rec, fraction
    !> The share of the rod's mass at the slider's pin.
    real(wp), intent(in) :: share
    !> Crank radius and rod length, m; crank speed, rad/s.
    real(wp), intent(in) :: r, l, omega
    character(len=:), allocatable :: kg, m, n_unit
    kg = unit_symbol("kg", lang)
    m = unit_symbol("m", lang)
    n_unit = unit_symbol("N", lang)
    if (lang == lang_ru) then
      call report%put("частичное уравновешивание "// &
        "кривошипно-ползунного механизма"//which_ru//": масса кривошипа, "// &
        "вращающаяся масса "//short_number(m_rot)//" "//kg//" и доля "//short_number(fraction)// &
        " возвратно-поступательно движущейся массы "// &
        short_number(m_rec)//" "//kg// &
        " на радиусе кривошипа "//short_number(r)//" "//m)
      call report%put("  (масса шатуна разнесена в две точки: доля "// &
        short_number(share)//" в шарнире ползуна)")
      call report%put("  сила инерции первого порядка (первая "// &
        "гармоника, m_rec*r*omega1^2 = "// &
        short_number(m_rec * r * omega**2)//" "//n_unit//" при omega1 = "//short_number(omega)//" "// &
        unit_symbol("rad/s", lang)//"): вдоль направляющей "// &
        short_number(m_rec * r * omega**2)//" "//n_unit// &
        " до уравновешивания, "//short_number((1.0_wp - fraction) * m_rec * r * omega**2)//" "//n_unit// &
        " после; поперек направляющей 0 до, "// &
        short_number(fraction * m_rec * r * omega**2)//" "//n_unit//" после")
      call report%put("  сила инерции второго порядка (вторая "// &
        "гармоника, m_rec*r*omega1^2*r/l): "// &
        short_number(m_rec * r * omega**2 * r / l)//" "//n_unit// &
        " вдоль направляющей, не меняется "// &
        "(противовес на кривошипе вращается с угловой "// &
        "скоростью omega1)")
    else
      call report%put("partial balance of the slider-crank"//which_en//": the crank's own mass, the rotating mass "// &
        short_number(m_rot)//" kg and "//short_number(fraction)//" of the reciprocating mass "// &
        short_number(m_rec)//" kg at the crank radius "//short_number(r)//" m")
      call report%put("  (rod as two masses: "//short_number(share)//" of it at the slider's pin)")
      call report%put("  primary component (first harmonic, m_rec*r*omega1^2 = "// &
        short_number(m_rec * r * omega**2)//" N at omega1 = "//short_number(omega)//" rad/s): along the "// &
        "guide "//short_number(m_rec * r * omega**2)//" N before, "// &
        short_number((1.0_wp - fraction) * m_rec * r * omega**2)//" N after; across the guide 0 before, "// &
        short_number(fraction * m_rec * r * omega**2)//" N after")
      call report%put("  secondary component (second harmonic, m_rec*r*omega1^2*r/l): "// &
        short_number(m_rec * r * omega**2 * r / l)//" N along the guide, unchanged (a crank counterweight "// &
        "turns at omega1 only)")
    end if
  end subroutine report_partial_balance

  !> A counterweight's note (the report's line, the comment of the mass assignment): "counterweight
  !> on link 2: 0.5 kg at r = 0.1 m, 30 deg <where> (m*r = 0.05 kg*m)".
  pure function counterweight_note(lang, id, mc, radius, angle, where_en, where_ru) result(note)
    integer, intent(in) :: lang
    !> The link's number in the deck.
    integer, intent(in) :: id
    !> The counterweight's mass, kg, its radius, m, and its angle, deg.
    real(wp), intent(in) :: mc, radius, angle
    !> What the angle is measured from, in English and in Russian.
    character(*), intent(in) :: where_en, where_ru
    character(len=:), allocatable :: note
    if (lang == lang_ru) then
      note = "противовес на звене "//int_str(id)//": "//short_number(mc)//" "//unit_symbol("kg", lang)// &
        " на радиусе r = "//short_number(radius)//" "//unit_symbol("m", lang)//", "//short_number(angle)//" "// &
        unit_symbol("deg", lang)//" "//where_ru//" (m*r = "//short_number(mc * radius)//" "// &
        unit_symbol("kg", lang)//"·"//unit_symbol("m", lang)//")"
    else
      note = "counterweight on link "//int_str(id)//": "//short_number(mc)//" kg at r = "// &
        short_number(radius)//" m, "//short_number(angle)//" deg "//where_en//" (m*r = "// &
        short_number(mc * radius)//" kg*m)"
    end if
  end function counterweight_note

  !> A counterweight's deck assignments (the mass with the note in a comment, the moment of
  !> inertia, the centre of mass) and its report lines (the note; the mass, moment of inertia
  !> and centre of mass before and after).
  pure subroutine add_counterweight_assignments(overrides, report, lang, method, note, m_name, j_name, s_name, &
                                                m_old, m_new, j_old, j_new, s_old, s_new, s_deck, where_en, where_ru)
    type(override_t), allocatable, intent(inout) :: overrides(:)
    type(text_buffer_t), intent(inout) :: report
    integer, intent(in) :: lang
    !> balance_full, balance_crank or balance_partial.
    integer, intent(in) :: method
    !> The counterweight's note.
    character(*), intent(in) :: note
    !> The deck's names of the link's mass, moment of inertia and centre of mass.
    character(*), intent(in) :: m_name, j_name, s_name
    !> Mass, kg, and moment of inertia, kg*m^2, before and after.
    real(wp), intent(in) :: m_old, m_new, j_old, j_new
    !> Centre of mass before and after, as the report gives it, and as the deck gives it, m.
    real(wp), intent(in) :: s_old(2), s_new(2), s_deck(2)
    !> Where the centres of mass are given, in English and in Russian.
    character(*), intent(in) :: where_en, where_ru
    call append_override(overrides, m_name, full_number(m_new)//"   ! "//note//"; kinetostat balance "// &
      "--method "//trim(balance_method_names(method)))
    call append_override(overrides, j_name, full_number(j_new))
    call append_override(overrides, s_name, full_number(s_deck(1))//", "//full_number(s_deck(2)))
    call report%put(note)
    call report%put("  "//m_name//" "//short_number(m_old)//" -> "//short_number(m_new)//" "// &
      unit_symbol("kg", lang)//", "//j_name//" "//short_number(j_old)//" -> "//short_number(j_new)//" "// &
      unit_symbol("kg*m^2", lang)//in_language(", centre of mass (", ", центр масс (", lang)// &
      short_number(s_old(1))//", "//short_number(s_old(2))//") -> ("//short_number(s_new(1))//", "// &
      short_number(s_new(2))//") "//unit_symbol("m", lang)//in_language(where_en, where_ru, lang))
  end subroutine add_counterweight_assignments

end module kinetostat_counterweights
