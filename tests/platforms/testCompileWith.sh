#!/bin/bash
# etc/openfoam13/compileWith, the compile-command prefix of the OpenFOAM-13
# build, on the command shapes of wmake's rules: a plain compile, and
# flex/bison rules whose steps wmake joins by a literal '&&' (a from-scratch
# build once failed at src/surfMesh's flex++ rule: "flex: can't open &&").
compileWith="$(cd "${0%/*}/../.." && pwd)/etc/openfoam13/compileWith"
failures=0
check()
{
    local what="$1" expected="$2" got="$3"
    if [ "$got" = "$expected" ]; then
        echo "ok: $what"
    else
        echo "FAILED: $what: expected [$expected], got [$got]"
        failures=$((failures + 1))
    fi
}

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

check "a plain compile gets -O1 last" "cc -c a.C -O1" \
    "$("$compileWith" echo cc -c a.C)"
check "ROUGHWALL_OPENFOAM13_OPT sets the level" "cc -c a.C -O3" \
    "$(ROUGHWALL_OPENFOAM13_OPT=-O3 "$compileWith" echo cc -c a.C)"
check "arguments with spaces stay whole" "[-DX=a b] [-O1]" \
    "$("$compileWith" printf '[%s] ' '-DX=a b' | sed 's/ $//')"

# flex++ rule: flex writes a file, the compiler step reads it; only the
# compiler gets the -O
out="$("$compileWith" sh -c 'echo scanner > lexer.C' '&&' \
      sh -c 'cat lexer.C; echo "compiler args: $*"' cc -c lexer.C)"
check "steps joined by && run in order, -O on the last only" \
    "scanner
compiler args: -c lexer.C -O1" "$out"

# bison rule: four steps
out="$("$compileWith" sh -c 'echo parser > y.tab.c' '&&' mv y.tab.c p.C \
      '&&' true '&&' sh -c 'cat p.C; echo "$*"' cc -c p.C)"
check "four steps" "parser
-c p.C -O1" "$out"

# a failing step stops the rule with its status; the compiler does not run
"$compileWith" sh -c 'exit 3' '&&' touch compiled
check "a failing step's status is the rule's" 3 "$?"
check "no step after a failing one runs" no "$([ -e compiled ] && echo yes || echo no)"

"$compileWith" sh -c 'exit 0' '&&' sh -c 'exit 5'
check "the compiler's status is the rule's" 5 "$?"

[ $failures -eq 0 ] && echo "compileWith: all checks passed"
exit $failures
