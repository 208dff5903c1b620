# wavefront-completion.bash — bash completion for `wavefront`, installed as
# share/bash-completion/completions/wavefront. The commands, each one's flags
# and a flag's choices ({refill,passes,...} in --help) are read from the
# program's own --help, so they are never out of date; --device offers the
# indices `wavefront devices` lists.
_wavefront() {
  local current=${COMP_WORDS[COMP_CWORD]} previous=${COMP_WORDS[COMP_CWORD-1]} command=() word
  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    case $word in
      render|devices|cache) command=("$word") ;;
      warm|clear) [[ ${command[0]} == cache && ${#command[@]} -eq 1 ]] && command+=("$word") ;;
    esac
  done
  if [[ ${#command[@]} -eq 0 ]]; then
    mapfile -t COMPREPLY < <(compgen -W "render devices cache --help --version" -- "$current")
    return
  fi
  if [[ ${command[0]} == cache && ${#command[@]} -eq 1 ]]; then
    mapfile -t COMPREPLY < <(compgen -W "warm clear --help" -- "$current")
    return
  fi
  local help
  help=$("${COMP_WORDS[0]}" "${command[@]}" --help 2>/dev/null)
  case $previous in
    -o|--output|--env|--reference|--report|--stats-json|--resume|--config)
      mapfile -t COMPREPLY < <(compgen -f -- "$current"); return ;;
    --cache-dir)
      mapfile -t COMPREPLY < <(compgen -d -- "$current"); return ;;
    --device)
      local indices
      indices=$("${COMP_WORDS[0]}" devices 2>/dev/null | sed -n 's/^\[\([0-9]*\)\].*/\1/p')
      mapfile -t COMPREPLY < <(compgen -W "$indices cpu gpu all" -- "$current"); return ;;
    --*)
      # A flag with choices: its line in --help reads `--flag TYPE:{a,b,c}`.
      local choices
      choices=$(grep -oE -- "^ +(-[a-z],)?$previous [A-Z]+:\{[^}]*\}" <<<"$help" | sed 's/.*{\(.*\)}/\1/; s/,/ /g')
      if [[ -n $choices ]]; then
        if [[ $previous == --aov ]]; then # a comma-separated list: complete its last name
          local done_part=""
          [[ $current == *,* ]] && done_part=${current%,*},
          mapfile -t COMPREPLY < <(compgen -P "$done_part" -W "$choices" -- "${current##*,}")
          compopt -o nospace 2>/dev/null
        else
          mapfile -t COMPREPLY < <(compgen -W "$choices" -- "$current")
        fi
        return
      fi ;;
  esac
  if [[ $current == -* ]]; then
    local flags
    flags=$(grep -oE -- '--[a-z][a-z0-9-]*' <<<"$help" | sort -u)
    mapfile -t COMPREPLY < <(compgen -W "$flags" -- "$current")
  elif [[ ${command[0]} == render || ${command[1]} == warm ]]; then # scenes
    mapfile -t COMPREPLY < <(compgen -f -X '!*.@(gltf|glb)' -- "$current"; compgen -d -- "$current")
  fi
}
complete -o filenames -F _wavefront wavefront
