#!/usr/bin/python3
"""Writes src/deck/catalog_material_data.f90: the behaviour keywords of Code_Aster's
DEFI_MATERIAU, as parasol catalog data (doc/deck-language.md, "Materials as data").

Code_Aster's command catalog is parasol's specification. This tool reads the DEFI_MATERIAU
description of a Code_Aster source tree (code_aster/Cata/Commands/defi_materiau.py, a
checkout of ZOHAIUB/code_aster or any other) with stand-in classes for its FACT, SIMP,
BLOC and rule objects, and writes for each behaviour (factor keyword) its simple keywords:
name, type, mandatory, cardinality, default, allowed values and range, and its rules
(EXCLUS, UN_PARMI, AU_MOINS_UN, NON_VIDE, PRESENT_PRESENT, PRESENT_ABSENT, ENSEMBLE).

Conditional blocks (BLOC) are flattened: their keywords become optional and lose their
defaults (the condition decides in Code_Aster whether they apply; parasol keeps what the
deck gives, as data); a behaviour described in several blocks gets the union of its
keywords, all optional, without rules; hidden keywords (statut 'c') are left out. ELAS and DIS_CONTACT, which parasol uses, are described by hand in
catalog_materials.f90 and skipped here.

The table is a list of tokens (catalog_materials.f90 decodes it):
  @NAME                       a behaviour (factor keyword, one occurrence)
  KEY:TYPES[!][*N][#N][=DEF][{A|B}][<LO,HI>]
      TYPES: letters R real, I integer, T text, F fonction, O formule, N nappe, B table,
      C complex (no complex in the deck language: any value is accepted); ! mandatory;
      *N at most N values (*0 = any number); #N at least N values; =DEF default (values
      of a list separated by /); {..} allowed values;
      <LO,HI> inclusive range (either side may be empty)
  %RULE:A,B,...               a rule over keywords of the behaviour (or, before the first
                              @, of the command)

usage: tools/aster_material_table.py CODE_ASTER_SOURCE_DIR > src/deck/catalog_material_data.f90
"""
import argparse
import os
import re
import sys

SKIP = {'ELAS', 'DIS_CONTACT'}
TYPE_LETTERS = {'R': 'R', 'I': 'I', 'TXM': 'T', 'fonction_sdaster': 'F', 'formule': 'O',
                'nappe_sdaster': 'N', 'table_sdaster': 'B', 'C': 'C'}


class Node:
    def __init__(self, kind, *args, **kw):
        self.kind, self.args, self.kw = kind, args, kw


class TypeName:
    def __init__(self, name):
        self.name = name

    def __call__(self, *args, **kw):
        return None


def load_command(path, name):
    source = open(path, encoding='utf-8').read()
    source = re.sub(r'^(from|import) .*$', '', source, flags=re.M)
    names = {k: (lambda kind: lambda *a, **k: Node(kind, *a, **k))(k)
             for k in ('FACT', 'SIMP', 'BLOC', 'OPER', 'MACRO', 'PROC')}
    for rule in ('EXCLUS', 'UN_PARMI', 'AU_MOINS_UN', 'PRESENT_PRESENT', 'PRESENT_ABSENT',
                 'ENSEMBLE', 'NON_VIDE', 'AU_PLUS_UN'):
        names[rule] = (lambda kind: lambda *a, **k: Node(kind, *a, **k))(rule)
    names.update(tr=lambda s: s, OPS=lambda s: s, _F=dict, pi=3.141592653589793)

    class Scope(dict):
        def __missing__(self, key):
            return names.get(key, TypeName(key))
    scope = Scope(names)
    exec(compile(source, path, 'exec'), scope)
    return scope[name]


def rules_of(node):
    rules = node.kw.get('regles', ())
    if isinstance(rules, Node):
        rules = (rules,)
    return list(rules)


def simple_keywords(node, in_bloc=False):
    """(name, SIMP node, inside a BLOC) of a factor keyword, blocks flattened."""
    out = []
    for key, value in node.kw.items():
        if not isinstance(value, Node):
            continue
        if value.kind == 'SIMP':
            out.append((key, value, in_bloc))
        elif value.kind == 'BLOC':
            out += simple_keywords(value, True)
    return out


def number(x):
    text = repr(float(x)) if isinstance(x, float) else str(x)
    return text


def type_letters(typ):
    types = typ if isinstance(typ, (tuple, list)) else (typ,)
    letters = ''
    for t in types:
        name = t.name if isinstance(t, TypeName) else t
        letters += TYPE_LETTERS[name]
    return letters


def keyword_token(key, simp, in_bloc):
    kw = simp.kw
    token = key + ':' + type_letters(kw['typ'])
    if kw.get('statut') == 'o' and not in_bloc:
        token += '!'
    mx = kw.get('max', 1)
    if mx != 1:
        token += '*' + ('0' if mx == '**' else str(mx))
    if kw.get('min', 1) != 1:
        token += '#' + str(kw['min'])
    if 'defaut' in kw and kw['defaut'] is not None and not in_bloc:
        default = kw['defaut']
        if isinstance(default, (tuple, list)):
            default = '/'.join(number(d) for d in default)
        else:
            default = number(default)
        if ' ' in default:
            raise SystemExit(f'{key}: a default with blanks: {default!r}')
        token += '=' + default
    if kw.get('into'):
        token += '{' + '|'.join(number(v) for v in kw['into']) + '}'
    if 'val_min' in kw or 'val_max' in kw:
        token += '<' + (number(kw['val_min']) if 'val_min' in kw else '') + ',' + \
            (number(kw['val_max']) if 'val_max' in kw else '') + '>'
    return token


def rule_token(rule, keys):
    names = list(rule.args) if rule.kind != 'NON_VIDE' else keys
    if rule.kind == 'NON_VIDE':
        return '%AU_MOINS_UN:' + ','.join(names)
    return '%' + rule.kind + ':' + ','.join(names)


def factors(command):
    """(name, FACT node) of the command, top-level blocks flattened."""
    out = []
    for key, value in command.kw.items():
        if isinstance(value, Node) and value.kind == 'FACT':
            out.append((key, value))
        elif isinstance(value, Node) and value.kind == 'BLOC':
            out += factors(value)
    return out


def tokens(command):
    result = []
    for rule in rules_of(command):
        result.append(rule_token(rule, []))
    versions = {}
    for name, fact in factors(command):
        versions.setdefault(name, []).append(fact)
    for name, facts in versions.items():
        if name in SKIP:
            continue
        # a behaviour described in several blocks (the THM ones, one per COMP_THM): the
        # union of their keywords, all optional, without defaults or rules
        several = len(facts) > 1
        result.append('@' + name)
        keys, done = [], set()
        for fact in facts:
            for key, simp, in_bloc in simple_keywords(fact):
                if key in done or simp.kw.get('statut') == 'c':
                    continue
                done.add(key)
                keys.append(key)
                result.append(keyword_token(key, simp, in_bloc or several))
        if not several:
            for rule in rules_of(facts[0]):
                result.append(rule_token(rule, keys))
    return result


def fortran(tokens, source):
    text = ' '.join(tokens)
    width = 64
    chunks = [text[i:i + width] for i in range(0, len(text), width)]
    body = []
    for k, chunk in enumerate(chunks):
        first, last = k * width + 1, k * width + len(chunk)
        body.append(f"        t({first}:{last}) = '{chunk}'")
    body = '\n'.join(body)
    return f"""!> GENERATED by tools/aster_material_table.py from Code_Aster's DEFI_MATERIAU catalog
!> ({source}):
!> the behaviour keywords parasol accepts as data (catalog_materials.f90 decodes the
!> tokens; the tool's header describes them). Do not edit by hand: rerun the tool on a
!> Code_Aster source tree.
module catalog_material_data
    implicit none
    private
    !> Length of the table text.
    integer, parameter, public :: MATERIAL_TABLE_LENGTH = {len(text)}
    public :: material_table
contains
    !> The table: blank-separated tokens.
    subroutine material_table(t)
        character(len=MATERIAL_TABLE_LENGTH), intent(out) :: t
{body}
    end subroutine material_table
end module catalog_material_data
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('aster_dir', help='a Code_Aster source tree')
    args = parser.parse_args()
    path = os.path.join(args.aster_dir, 'code_aster', 'Cata', 'Commands', 'defi_materiau.py')
    command = load_command(path, 'DEFI_MATERIAU')
    sys.stdout.write(fortran(tokens(command), 'code_aster/Cata/Commands/defi_materiau.py'))


if __name__ == '__main__':
    main()
