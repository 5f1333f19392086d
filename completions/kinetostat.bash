# Bash completion for kinetostat: subcommands, each one's options, kinds, formats, languages,
# and deck files (*.nml) or outputs (*.table, *.csv, *.txt) as arguments. The lists follow
# `kinetostat --help` (tools/check_options.py checks them against it).
# Use: source completions/kinetostat.bash (or copy it to
# ~/.local/share/bash-completion/completions/kinetostat).
_kinetostat() {
  local cur prev
  cur="${COMP_WORDS[COMP_CWORD]}"
  prev="${COMP_WORDS[COMP_CWORD-1]}"
  local kinds="pr3207 pr3050 sixbar assur gears cam linkage gear_geometry planetary_synthesis cam_profile fourbar engine"
  local command="${COMP_WORDS[1]}"
  local opts
  case "$command" in
    sweep) opts="--vary --set --part --jobs --keep-going --format --shaking -o --output --max-deck-size --allow-selfcheck-failure -q --quiet --strict" ;;
    template) opts="-o --output" ;;
    diff) opts="--rtol --atol --common -q --quiet" ;;
    balance) opts="-o --output --method --fraction --lang --max-deck-size -q --quiet" ;;
    structure) opts="--lang -o --output --max-deck-size -q --quiet" ;;
    convert) opts="--to -o --output --max-deck-size -q --quiet" ;;
    contour) opts="--set -o --output --max-deck-size -q --quiet" ;;
    sheets) opts="-o --output --paper --lang --at --designation --sheet-numbers --positions --point --output-link --student --group --variant --set --max-deck-size -q --quiet" ;;
    *) command=""
       opts="--set -o --output --format --pairs --at --plans --lang --kinematics --frame --shaking --student --group --variant --max-deck-size --allow-selfcheck-failure -q --quiet --strict --version" ;;
  esac
  case "$prev" in
    --format)
      if [ "$command" = sweep ]; then COMPREPLY=($(compgen -W "summary npy" -- "$cur"))
      else COMPREPLY=($(compgen -W "table csv json svg summary plans dxf deck npy" -- "$cur")); fi
      return ;;
    --frame) COMPREPLY=($(compgen -W "global link" -- "$cur")); return ;;
    --lang) COMPREPLY=($(compgen -W "en ru" -- "$cur")); return ;;
    --method) COMPREPLY=($(compgen -W "full crank partial" -- "$cur")); return ;;
    --paper) COMPREPLY=($(compgen -W "A1 A2 A3 A4" -- "$cur")); return ;;
    --positions) COMPREPLY=($(compgen -W "8 12" -- "$cur")); return ;;
    --to) COMPREPLY=($(compgen -W "linkage" -- "$cur")); return ;;
    -o|--output)
      if [ "$command" = sheets ]; then COMPREPLY=($(compgen -d -- "$cur")); else COMPREPLY=($(compgen -f -- "$cur")); fi
      return ;;
    template) COMPREPLY=($(compgen -W "$kinds" -- "$cur")); return ;;
    --rtol|--atol|--set|--pairs|--at|--vary|--part|--jobs|--max-deck-size|--fraction|--student|--group|--variant|--designation|--sheet-numbers|--point|--output-link)
      COMPREPLY=(); return ;;
  esac
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$opts --help" -- "$cur"))
  elif [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "sweep template diff balance structure convert contour sheets -" -- "$cur") \
      $(compgen -f -X '!*.nml' -- "$cur") $(compgen -d -- "$cur"))
  elif [ "$command" = diff ]; then
    COMPREPLY=($(compgen -f -X '!*.@(table|csv|txt|out)' -- "$cur") $(compgen -d -- "$cur"))
  elif [ "$command" = template ]; then
    COMPREPLY=()
  else
    COMPREPLY=($(compgen -f -X '!*.nml' -- "$cur") $(compgen -d -- "$cur"))
  fi
}
shopt -s extglob 2>/dev/null
complete -o filenames -F _kinetostat kinetostat
