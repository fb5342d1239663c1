#!/bin/bash
# completion_test.sh AFFORD: the script of `afford completion bash` is valid
# bash, and sourced, its function completes commands, options and values:
#   afford r<TAB>            -> render replay rules run
#   afford run --r<TAB>      -> --record --runs
#   afford run --out cl<TAB> -> folders only (cli/, not a file)
#   afford check CMakeL<TAB> -> files (CMakeLists.txt)
# Run from the source folder.
afford=$1
script=$("$afford" completion bash) || { echo "completion_test: afford completion bash failed" >&2; exit 1; }
bash -n <(printf '%s\n' "$script") || { echo "completion_test: the script is not valid bash" >&2; exit 1; }
source <(printf '%s\n' "$script")
fail=0

# complete WORD... : the sorted completions of the last word.
complete_words() {
  COMP_WORDS=(afford "$@")
  COMP_CWORD=$#
  COMPREPLY=()
  _afford
  [ ${#COMPREPLY[@]} -eq 0 ] || printf "%s\n" "${COMPREPLY[@]}" | sort | tr "\n" " "
}

expect() {
  local want=$1
  shift
  local got
  got=$(complete_words "$@")
  if [ "$got" != "$want" ]; then
    echo "completion_test: afford $* completes to '$got', expected '$want'" >&2
    fail=1
  fi
}

expect "render replay rules run " r
expect "--record --runs " run --r
expect "cli " run --out cl
expect "CMakeLists.txt " check CMakeL
expect "--coverage " test --cov
expect "" run --runs ""
exit $fail
