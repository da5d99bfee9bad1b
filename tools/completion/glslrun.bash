# bash completion for glslrun. Options are read from the command's own
# `glslrun [SUBCOMMAND] --help` when completing, so they follow the binary.
_glslrun() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]} sub="" i
    for ((i = 1; i < COMP_CWORD; i++)); do
        case ${COMP_WORDS[i]} in test | batch | trace | check | serve) sub=${COMP_WORDS[i]}; break ;; esac
    done
    COMPREPLY=()
    case $prev in
    --precision) mapfile -t COMPREPLY < <(compgen -W "reference precise fast" -- "$cur"); return ;;
    --backend) mapfile -t COMPREPLY < <(compgen -W "interp jit auto" -- "$cur"); return ;;
    --jit-tier) mapfile -t COMPREPLY < <(compgen -W "tiered first optimised" -- "$cur"); return ;;
    --error-report | --cache-dir | --dump-fixed-function)
        compopt -o filenames 2> /dev/null || true  # outside a completion (tests) it fails
        mapfile -t COMPREPLY < <(compgen -d -- "$cur")
        return
        ;;
    esac
    if [[ $cur == -* ]]; then
        local options
        options=$("${COMP_WORDS[0]}" $sub --help 2> /dev/null |
            grep -oE -- '(^|[ ,])--?[A-Za-z][A-Za-z0-9-]*' | tr -d ' ,' | sort -u)
        mapfile -t COMPREPLY < <(compgen -W "$options" -- "$cur")
        return
    fi
    compopt -o filenames 2> /dev/null || true  # outside a completion (tests) it fails
    mapfile -t COMPREPLY < <(compgen -f -- "$cur")
    if [[ -z $sub && $COMP_CWORD -eq 1 ]]; then
        local commands
        mapfile -t commands < <(compgen -W "test batch trace check serve" -- "$cur")
        COMPREPLY+=("${commands[@]}")
    fi
}
complete -F _glslrun glslrun
