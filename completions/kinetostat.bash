# Bash completion for kinetostat: subcommands, options, kinds, formats, languages, and
# deck files (*.nml) or outputs (*.table, *.csv, *.txt) as arguments.
# Use: source completions/kinetostat.bash (or copy it to
# ~/.local/share/bash-completion/completions/kinetostat).
_kinetostat() {
  local cur prev words cword
  cur="${COMP_WORDS[COMP_CWORD]}"
  prev="${COMP_WORDS[COMP_CWORD-1]}"
  local kinds="pr3207 pr3050 sixbar assur gears cam linkage gear_geometry planetary_synthesis cam_profile fourbar engine"
  local run_opts="-o --output --set --format --pairs --at --plans --student --group --variant --lang --kinematics --frame --max-deck-size --allow-selfcheck-failure --quiet --strict --help --version"
  case "$prev" in
    --format) COMPREPLY=($(compgen -W "table csv json svg summary plans dxf deck npy" -- "$cur")); return ;;
    --frame) COMPREPLY=($(compgen -W "global link" -- "$cur")); return ;;
    --lang) COMPREPLY=($(compgen -W "en ru" -- "$cur")); return ;;
    -o|--output) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    template) COMPREPLY=($(compgen -W "$kinds" -- "$cur")); return ;;
    --rtol|--atol|--set|--pairs|--at|--vary|--part|--jobs|--max-deck-size) COMPREPLY=(); return ;;
  esac
  case "${COMP_WORDS[1]}" in
    diff)
      if [[ "$cur" == -* ]]; then
        COMPREPLY=($(compgen -W "--rtol --atol --common --quiet --help" -- "$cur"))
      else
        COMPREPLY=($(compgen -f -X '!*.@(table|csv|txt|out)' -- "$cur") $(compgen -d -- "$cur"))
      fi
      return ;;
    template)
      COMPREPLY=($(compgen -W "-o --output" -- "$cur")); return ;;
    sweep)
      if [[ "$cur" == -* ]]; then
        COMPREPLY=($(compgen -W "--vary --set --part --jobs --keep-going -o --output --max-deck-size --allow-selfcheck-failure --quiet --strict --help" -- "$cur"))
      else
        COMPREPLY=($(compgen -f -X '!*.nml' -- "$cur") $(compgen -d -- "$cur"))
      fi
      return ;;
  esac
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$run_opts" -- "$cur"))
  elif [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "template diff sweep contour -" -- "$cur") $(compgen -f -X '!*.nml' -- "$cur") $(compgen -d -- "$cur"))
  else
    COMPREPLY=($(compgen -f -X '!*.nml' -- "$cur") $(compgen -d -- "$cur"))
  fi
}
shopt -s extglob 2>/dev/null
complete -o filenames -F _kinetostat kinetostat
