# wavefront-completion.bash — bash completion for `wavefront`, installed as
# share/bash-completion/completions/wavefront. The commands and each one's
# flags are read from the program's own --help, so they are never out of date.
_wavefront() {
  local current=${COMP_WORDS[COMP_CWORD]} previous=${COMP_WORDS[COMP_CWORD-1]} command="" word
  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    case $word in render|devices|cache) command=$word; break ;; esac
  done
  if [[ -z $command ]]; then
    mapfile -t COMPREPLY < <(compgen -W "render devices cache --help --version" -- "$current")
    return
  fi
  case $previous in # flags that take a file: complete paths
    -o|--output|--env|--reference|--report|--stats-json|--resume|--config|--cache-dir)
      mapfile -t COMPREPLY < <(compgen -f -- "$current"); return ;;
  esac
  if [[ $current == -* ]]; then
    local flags
    flags=$("${COMP_WORDS[0]}" "$command" --help 2>/dev/null | grep -oE -- '--[a-z][a-z0-9-]*' | sort -u)
    mapfile -t COMPREPLY < <(compgen -W "$flags" -- "$current")
  elif [[ $command == cache && COMP_CWORD -eq 2 ]]; then
    mapfile -t COMPREPLY < <(compgen -W "warm clear" -- "$current")
  else # scenes
    mapfile -t COMPREPLY < <(compgen -f -X '!*.@(gltf|glb)' -- "$current"; compgen -d -- "$current")
  fi
}
complete -o filenames -F _wavefront wavefront
