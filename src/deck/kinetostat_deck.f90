!> Deck (namelist file) plumbing shared by every mechanism, in one `use`: loading the deck
!> once into memory (kinetostat_deck_source), namelist lexing, the syntax pre-check and the
!> probe of a failed READ (kinetostat_deck_namelist), and the validation rules that name the
!> file, the group, the variable and the reason (kinetostat_deck_rules).
module kinetostat_deck
  use kinetostat_deck_source, only: deck_context_t, deck_source_t, load_deck, deck_source_from_text, &
    stdin_deck_path, stdin_deck_name, deck_line_count, deck_line, deck_line_length, release_deck_text, &
    max_deck_size, set_max_deck_size, default_max_deck_size
  use kinetostat_deck_namelist, only: max_deck_array, title_chars, text_chars, text_bytes, &
    read_group_name, namelist_failure, namelist_probe_t, check_namelist_syntax, longest_quoted, begin_group, &
    deck_array_capacities, assignment_starts, comment_start
  use kinetostat_deck_rules, only: unset_real, unset_bits, max_steps, deck_error, require_all_set, &
    values_out_of_memory, is_set, require_set, require_positive, require_nonnegative, require_rule, &
    require_per_step, is_whole_in, require_whole, require_chars, optional_default, count_values, &
    steps_over_turn, deck_rules_t, rule_finite, rule_positive, rule_nonnegative, angle_steps_t, step_angle_deg
  implicit none
  private
  public :: deck_context_t, unset_real, unset_bits, max_deck_array, max_steps
  public :: deck_source_t, load_deck, deck_source_from_text, stdin_deck_path, stdin_deck_name
  public :: deck_line_count, deck_line, deck_line_length, release_deck_text
  public :: read_group_name, namelist_failure, deck_error, namelist_probe_t, require_all_set
  public :: is_set, require_set, require_positive, require_nonnegative, require_rule, require_per_step
  public :: is_whole_in, require_whole, require_chars, title_chars, text_chars, text_bytes
  public :: optional_default, count_values, steps_over_turn
  public :: check_namelist_syntax, longest_quoted, begin_group
  public :: deck_array_capacities, max_deck_size, set_max_deck_size, default_max_deck_size, assignment_starts
  public :: comment_start
  public :: values_out_of_memory, deck_rules_t, rule_finite, rule_positive, rule_nonnegative
  public :: angle_steps_t, step_angle_deg
end module kinetostat_deck
