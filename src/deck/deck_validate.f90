!> Validation of one command call against its catalog entry (deck_catalog_data): unknown
!> keywords (with "did you mean"), types, cardinality, allowed values, mandatory keywords,
!> rules (EXCLUS, UN_PARMI, AU_MOINS_UN, PRESENT_PRESENT, PRESENT_ABSENT, ENSEMBLE), then
!> defaults. Conditional blocks (Code_Aster's BLOC) are decided first in each scope from
!> the keywords written there: a keyword of an inactive block is refused with the condition
!> it needs; the mandatory keywords, rules and defaults of inactive blocks do not apply.
!> Produces the command_t handlers receive.
module deck_validate
    use kinds, only: dp, i8
    use strings, only: string_t, to_text, join_words
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_value
    use deck_catalog, only: catalog_t, cmd_def_t, kw_def_t, find_keyword, split_words, MANY, &
        RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN, RULE_PRESENT_PRESENT, RULE_PRESENT_ABSENT, &
        RULE_ENSEMBLE, rule_t
    use deck_command, only: command_t, keyword_set_t, kw_value_t, factor_value_t
    use deck_concept, only: concept_display_name
    use deck_suggest, only: did_you_mean
    use deck_math, only: same_real
    implicit none
    private
    public :: validate_command, type_accepts, default_value

contains

    !> Validates the keyword arguments of a call to catalog command `icmd`.
    !>  cat : the catalog;  icmd : index of the command in it
    !>  args : VK_FACTOR value holding the keyword arguments and their locations
    !>  file, line, col : where the command name is written
    !>  cmd : out, the validated command, defaults filled
    !>  st : out, STATUS_DECK_ERROR located at the offending keyword or value
    subroutine validate_command(cat, icmd, args, file, line, col, cmd, st)
        type(catalog_t), intent(in) :: cat
        integer, intent(in) :: icmd, line, col
        type(value_t), intent(in) :: args
        character(len=*), intent(in) :: file
        type(command_t), intent(out) :: cmd
        type(status_t), intent(out) :: st
        integer :: j, k
        type(factor_value_t) :: factor
        type(value_list_t) :: a
        logical, allocatable :: active(:)
        a = unpack_value(args)
        associate (def => cat%cmds(icmd))
            cmd%name = def%name
            cmd%result_type = def%result_type
            cmd%file = file; cmd%command = def%name; cmd%scope = ''
            cmd%line = line; cmd%col = col
            allocate (cmd%items(8))
            active = active_blocs(def, 0, a)
            call check_scope(def, 0, a, active, file, st)
            if (st%failed()) return
            do j = 1, size(a%keys)
                if (a%keys(j)%s == 'reuse') then
                    call check_reuse(def, a, j, file, cmd, st)
                    if (st%failed()) return
                    cycle
                end if
                k = find_active(def, 0, a%keys(j)%s, active)
                if (k > 0) then
                    if (def%kws(k)%is_factor) then
                        call build_factor(def, k, a%items(j), file, a%key_line(j), &
                                          a%key_col(j), factor, st)
                        if (st%failed()) return
                        call cmd%add_factor(factor)
                        cycle
                    end if
                end if
                call add_simple(def, k, a, j, file, cmd, st)
                if (st%failed()) return
            end do
            call check_required(def, 0, a, active, file, line, col, st)
            if (st%failed()) return
            call fill_defaults(def, 0, active, cmd)
            if (associated(cmd%reuse)) call check_reused_keywords(def, cmd, st)
            cmd%result_type = call_result_type(def%result_type, cmd)
        end associate
    end subroutine validate_command

    !> The result type of one call. A catalog result type that depends on the call (Code_Aster's
    !> sd_prod functions) is written '@KEY': '@TYPE_CHAM' (CREA_CHAMP: NOEU_* cham_no_sdaster,
    !> CART_* carte_sdaster, EL*_* cham_elem), '@TYPE_RESU' (CREA_RESU: the lower-case
    !> TYPE_RESU), '@RESULTAT' (CALC_CHAMP, POST_CHAMP: the type of the RESULTAT concept),
    !> '@RESULTAT CHAM_GD' (MODI_REPERE: of the RESULTAT or CHAM_GD concept).
    function call_result_type(declared, cmd) result(type_name)
        character(len=*), intent(in) :: declared
        type(command_t), intent(in) :: cmd
        character(len=:), allocatable :: type_name
        type(value_t) :: v
        character(len=:), allocatable :: text
        integer :: i
        type_name = declared
        if (len(declared) < 2) return
        if (declared(1:1) /= '@') return
        v = cmd%get_value(declared(2:))
        select case (declared)
        case ('@TYPE_CHAM')
            if (v%kind /= VK_STR) return
            text = v%s
            if (len(text) < 4) return
            type_name = 'cham_elem'
            if (text(1:4) == 'NOEU') type_name = 'cham_no_sdaster'
            if (text(1:4) == 'CART') type_name = 'carte_sdaster'
        case ('@TYPE_RESU')
            if (v%kind /= VK_STR) return
            type_name = v%s
            do i = 1, len(type_name)
                if (type_name(i:i) >= 'A' .and. type_name(i:i) <= 'Z') type_name(i:i) = &
                    achar(iachar(type_name(i:i)) + 32)
            end do
        case ('@RESULTAT')
            if (v%kind == VK_CONCEPT) type_name = v%s
        case ('@RESULTAT CHAM_GD', '@RESULTAT CHAM_GD corresp_2_mailla')
            ! MODI_REPERE, PROJ_CHAMP: the type of what it is given; PROJ_CHAMP without
            ! either: the correspondence (corresp_2_mailla)
            v = cmd%get_value('RESULTAT')
            if (v%kind /= VK_CONCEPT) v = cmd%get_value('CHAM_GD')
            if (v%kind == VK_CONCEPT) then
                type_name = v%s
            else if (len(declared) > 18) then
                type_name = declared(19:)
            end if
        end select
    end function call_result_type

    !> Which conditional blocks of scope `parent` are active for the keywords `args` written
    !> there (blocks of other scopes: false). A block is active when its enclosing block is
    !> and its condition holds (bloc_t); a value condition reads the written value, else the
    !> default of the keyword in force (blocks are decided in catalog order, enclosing
    !> blocks first).
    function active_blocs(def, parent, args) result(active)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        type(value_list_t), intent(in) :: args
        logical, allocatable :: active(:)
        integer :: b, i, k
        character(len=:), allocatable :: value
        logical :: found
        allocate (active(def%nbloc), source=.false.)
        do b = 1, def%nbloc
            associate (bl => def%blocs(b))
                if (bl%parent /= parent) cycle
                if (bl%outer > 0) then
                    if (.not. active(bl%outer)) cycle
                end if
                if (any([(.not. given(args, bl%present(i)%s), i = 1, size(bl%present))])) cycle
                if (any([(given(args, bl%absent(i)%s), i = 1, size(bl%absent))])) cycle
                if (len(bl%key) > 0) then
                    call scope_value_text(args, bl%key, value, found)
                    if (.not. found) then
                        k = find_active(def, parent, bl%key, active)
                        if (k == 0) cycle
                        if (len(def%kws(k)%default) == 0) cycle
                        value = def%kws(k)%default
                    end if
                    if (.not. any([(bl%values(i)%s == value, i = 1, size(bl%values))])) cycle
                end if
                active(b) = .true.
            end associate
        end do
    end function active_blocs

    ! The text of the single value written for `name` in args (a text, or an integer's
    ! digits); found = false when the keyword is absent or not a single text or integer.
    subroutine scope_value_text(args, name, text, found)
        type(value_list_t), intent(in) :: args
        character(len=*), intent(in) :: name
        character(len=:), allocatable, intent(out) :: text
        logical, intent(out) :: found
        type(value_t) :: v
        integer :: j
        found = .false.
        text = ''
        do j = 1, size(args%keys)
            if (args%keys(j)%s /= name) cycle
            v = args%items(j)
            if ((v%kind == VK_TUPLE .or. v%kind == VK_LIST) .and. nitems(v) == 1) v = item(v, 1)
            if (v%kind == VK_STR) then
                text = v%s
                found = .true.
            else if (v%kind == VK_INT) then
                text = to_text(v%i)
                found = .true.
            end if
            return
        end do
    end subroutine scope_value_text

    !> Index of keyword `name` of scope `parent` that is in force: outside any block or in an
    !> active one; 0 if none.
    pure integer function find_active(def, parent, name, active) result(k)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        character(len=*), intent(in) :: name
        logical, intent(in) :: active(:)
        do k = 1, def%nkw
            if (def%kws(k)%parent /= parent .or. def%kws(k)%name /= name) cycle
            if (in_force(def%kws(k)%bloc, active)) return
        end do
        k = 0
    end function find_active

    !> True for block 0 (none) or an active block.
    pure logical function in_force(bloc, active)
        integer, intent(in) :: bloc
        logical, intent(in) :: active(:)
        in_force = bloc == 0
        if (bloc > 0) in_force = active(bloc)
    end function in_force

    ! "OPTION='SPHERE'" or "OPTION='SPHERE' (or OPTION='CYLINDRE')": the conditions of the
    ! blocks where keyword `name` of scope `parent` is valid.
    function bloc_conditions(def, parent, name) result(text)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        integer :: k, n
        text = ''
        n = 0
        do k = 1, def%nkw
            if (def%kws(k)%parent /= parent .or. def%kws(k)%name /= name) cycle
            if (def%kws(k)%bloc == 0) cycle
            n = n + 1
            if (n == 2) text = text // ' (or '
            if (n > 2) text = text // ', or '
            text = text // def%blocs(def%kws(k)%bloc)%text
        end do
        if (n > 1) text = text // ')'
    end function bloc_conditions

    !> reuse=CONCEPT (Code_Aster's catalog attribute `reentrant`, cmd_def_t): allowed when
    !> the command modifies a concept in place ('o' or 'f'); the concept must be of the
    !> command's result type. Sets cmd%reuse and keeps the keyword (cmd%has('reuse')).
    subroutine check_reuse(def, args, j, file, cmd, st)
        type(cmd_def_t), intent(in) :: def
        type(value_list_t), intent(in) :: args
        integer, intent(in) :: j
        character(len=*), intent(in) :: file
        type(command_t), intent(inout) :: cmd
        type(status_t), intent(inout) :: st
        type(kw_value_t) :: item
        associate (v => args%items(j))
            if (index('of', def%reentrant(1:1)) == 0 .or. len(def%result_type) == 0) then
                call fail('reuse is not allowed: ' // def%name // ' makes a new concept, it ' &
                    // 'does not modify one in place (Code_Aster''s catalog: reentrant=''n'')')
                return
            end if
            if (v%kind /= VK_CONCEPT .or. .not. associated(v%obj)) then
                call fail('expected the concept to modify in place (a concept of type ' // &
                    type_words(def%result_type) // '), got ' // describe(v)); return
            end if
            if (.not. type_accepts(def%result_type, v)) then
                call fail('expected ' // type_words(def%result_type) // ' (what ' // &
                    def%name // ' makes), got ' // describe(v)); return
            end if
            cmd%reuse => v%obj
            item%name = 'reuse'
            item%line = args%key_line(j); item%col = args%key_col(j)
            item%value = v
            call cmd%add(item)
        end associate
    contains
        subroutine fail(message)
            character(len=*), intent(in) :: message
            call set_error(st, STATUS_DECK_ERROR, message, file=file, &
                line=vline(args%items(j), args%key_line(j)), &
                column=vcol(args%items(j), args%key_col(j)), command=def%name, keyword='reuse')
        end subroutine fail
    end subroutine check_reuse

    !> The keywords Code_Aster's `reentrant` names after ':' ('o:MAILLAGE|GRILLE') give the
    !> concept the command reads and modifies: when one is given, it must be the reused one
    !> (DEFI_GROUP(reuse=MA, MAILLAGE=MA)), else the command would change one concept with
    !> what it computed on another.
    subroutine check_reused_keywords(def, cmd, st)
        type(cmd_def_t), intent(in) :: def
        type(command_t), intent(in) :: cmd
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        type(value_t) :: v
        character(len=:), allocatable :: spec
        integer :: i, colon
        colon = index(def%reentrant, ':')
        if (colon == 0) return
        spec = def%reentrant(colon + 1:)
        do i = 1, len(spec)
            if (spec(i:i) == '|') spec(i:i) = ' '
        end do
        call split_words(spec, names)
        do i = 1, size(names)
            if (.not. cmd%given(names(i)%s)) cycle
            v = cmd%get_value(names(i)%s)
            if (v%kind /= VK_CONCEPT) cycle
            if (associated(v%obj, cmd%reuse)) cycle
            call cmd%error_at('reuse', 'reuse names ' // concept_display_name(cmd%reuse) // &
                ' but ' // names(i)%s // ' gives ' // concept_display_name(v%obj) // ': ' // &
                def%name // ' modifies in place the concept it reads (write reuse=' // &
                concept_display_name(v%obj) // ', or leave reuse out for a new concept)', st)
            return
        end do
    end subroutine check_reused_keywords

    !> Unknown and repeated keywords of one scope (checked before the values), and keywords
    !> of a conditional block whose condition does not hold.
    subroutine check_scope(def, parent, args, active, file, st)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        type(value_list_t), intent(in) :: args
        logical, intent(in) :: active(:)
        character(len=*), intent(in) :: file
        type(status_t), intent(inout) :: st
        integer :: j, i, k
        do j = 1, size(args%keys)
            k = find_keyword(def, parent, args%keys(j)%s)
            if (parent == 0 .and. args%keys(j)%s == 'reuse') k = -1   ! check_reuse
            if (k == 0 .and. .not. (def%open_keywords .and. parent == 0)) then
                call set_error(st, STATUS_DECK_ERROR, 'unknown keyword ' // args%keys(j)%s // &
                    did_you_mean(args%keys(j)%s, scope_names(def, parent, active)) // &
                    ' (valid here: ' // join_words(scope_names(def, parent, active), ', ') // &
                    ')', file=file, line=args%key_line(j), column=args%key_col(j), &
                    command=def%name, keyword=path(def, parent, args%keys(j)%s))
                return
            end if
            if (k > 0) then
                if (find_active(def, parent, args%keys(j)%s, active) == 0) then
                    call set_error(st, STATUS_DECK_ERROR, 'keyword ' // args%keys(j)%s // &
                        ' is not valid here: it goes with ' // bloc_conditions(def, parent, &
                        args%keys(j)%s), file=file, line=args%key_line(j), &
                        column=args%key_col(j), command=def%name, &
                        keyword=path(def, parent, args%keys(j)%s))
                    return
                end if
            end if
            do i = 1, j - 1
                if (args%keys(i)%s == args%keys(j)%s) then
                    call set_error(st, STATUS_DECK_ERROR, 'keyword given twice', file=file, &
                        line=args%key_line(j), column=args%key_col(j), command=def%name, &
                        keyword=path(def, parent, args%keys(j)%s))
                    return
                end if
            end do
        end do
    end subroutine check_scope

    !> Mandatory keywords and rules of one scope (checked after the values, so a wrong
    !> value is reported at its keyword first).
    subroutine check_required(def, parent, args, active, file, line, col, st)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent, line, col
        type(value_list_t), intent(in) :: args
        logical, intent(in) :: active(:)
        character(len=*), intent(in) :: file
        type(status_t), intent(inout) :: st
        integer :: k
        do k = 1, def%nkw
            if (def%kws(k)%parent /= parent .or. .not. def%kws(k)%mandatory) cycle
            if (.not. in_force(def%kws(k)%bloc, active)) cycle
            if (.not. given(args, def%kws(k)%name)) then
                call set_error(st, STATUS_DECK_ERROR, 'missing mandatory keyword ' // &
                    def%kws(k)%name, file=file, line=line, column=col, command=def%name, &
                    keyword=path(def, parent, def%kws(k)%name))
                return
            end if
        end do
        call check_rules(def, parent, args, active, file, line, col, st)
    end subroutine check_required

    subroutine check_rules(def, parent, args, active, file, line, col, st)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent, line, col
        type(value_list_t), intent(in) :: args
        logical, intent(in) :: active(:)
        character(len=*), intent(in) :: file
        type(status_t), intent(inout) :: st
        integer :: r, i, count, last
        character(len=:), allocatable :: names, what
        do r = 1, def%nrule
            if (def%rules(r)%parent /= parent) cycle
            if (.not. in_force(def%rules(r)%bloc, active)) cycle
            count = 0; last = 0; names = ''
            do i = 1, size(def%rules(r)%names)
                if (i > 1) names = names // ' | '
                names = names // def%rules(r)%names(i)%s
                if (given(args, def%rules(r)%names(i)%s)) then
                    count = count + 1
                    if (count == 2) last = i
                end if
            end do
            what = ''
            select case (def%rules(r)%kind)
            case (RULE_EXCLUS)
                if (count > 1) what = 'keywords ' // names // ' exclude each other (give ' // &
                    'only one)'
            case (RULE_UN_PARMI)
                if (count > 1) what = 'give exactly one of ' // names // ', not several'
                if (count == 0) what = 'missing keyword: give exactly one of ' // names
            case (RULE_AU_MOINS_UN)
                if (count == 0) what = 'missing keyword: give at least one of ' // names
            case (RULE_PRESENT_PRESENT, RULE_PRESENT_ABSENT, RULE_ENSEMBLE)
                call conditional_rule(def%rules(r), args, what, last)
            end select
            if (len(what) == 0) cycle
            if (last > 0) then
                call set_error(st, STATUS_DECK_ERROR, what, file=file, &
                    line=key_line(args, def%rules(r)%names(last)%s), &
                    column=key_col(args, def%rules(r)%names(last)%s), command=def%name, &
                    keyword=path(def, parent, def%rules(r)%names(last)%s))
            else
                call set_error(st, STATUS_DECK_ERROR, what, file=file, line=line, column=col, &
                               command=def%name, keyword=scope_path(def, parent))
            end if
            return
        end do
    end subroutine check_rules

    !> PRESENT_PRESENT (the first keyword given needs every other), PRESENT_ABSENT (the first
    !> given forbids every other) and ENSEMBLE (all or none): the message, '' when the rule
    !> holds, and the keyword to locate it at (index in the rule, 0 = the scope).
    subroutine conditional_rule(rule, args, what, at)
        type(rule_t), intent(in) :: rule
        type(value_list_t), intent(in) :: args
        character(len=:), allocatable, intent(out) :: what
        integer, intent(out) :: at
        logical :: here(size(rule%names))
        integer :: i
        character(len=:), allocatable :: first
        what = ''
        at = 0
        do i = 1, size(rule%names)
            here(i) = given(args, rule%names(i)%s)
        end do
        first = rule%names(1)%s
        select case (rule%kind)
        case (RULE_PRESENT_PRESENT)
            if (.not. here(1)) return
            do i = 2, size(rule%names)
                if (here(i)) cycle
                what = first // ' needs ' // rule%names(i)%s // ' (give it too)'
                at = 1
                return
            end do
        case (RULE_PRESENT_ABSENT)
            if (.not. here(1)) return
            do i = 2, size(rule%names)
                if (.not. here(i)) cycle
                what = first // ' and ' // rule%names(i)%s // ' exclude each other ' // &
                    '(give only one)'
                at = i
                return
            end do
        case (RULE_ENSEMBLE)
            if (all(here) .or. .not. any(here)) return
            at = findloc(here, .true., dim=1)
            what = 'keywords ' // join_names(rule) // ' go together: give all or none ' // &
                '(missing ' // rule%names(findloc(here, .false., dim=1))%s // ')'
        end select
    end subroutine conditional_rule

    ! 'A | B | C'
    function join_names(rule) result(text)
        type(rule_t), intent(in) :: rule
        character(len=:), allocatable :: text
        integer :: i
        text = ''
        do i = 1, size(rule%names)
            if (i > 1) text = text // ' | '
            text = text // rule%names(i)%s
        end do
    end function join_names

    !> Occurrences of factor keyword k: a _F, or a tuple/list of _F.
    subroutine build_factor(def, k, v, file, line, col, factor, st)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: k, line, col
        type(value_t), intent(in) :: v
        character(len=*), intent(in) :: file
        type(factor_value_t), intent(out) :: factor
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: occs(:)
        type(value_list_t) :: list
        logical, allocatable :: active(:)
        integer :: i, j, kw
        factor%name = def%kws(k)%name
        factor%line = line; factor%col = col
        if (v%kind == VK_FACTOR) then
            allocate (occs(1))
            occs(1) = v
        else if (v%kind == VK_TUPLE .or. v%kind == VK_LIST) then
            list = unpack_value(v)
            occs = list%items
        else
            call set_error(st, STATUS_DECK_ERROR, 'expected _F(...) (a factor keyword), got ' &
                // kind_label(v), file=file, line=vline(v, line), column=vcol(v, col), &
                command=def%name, keyword=def%kws(k)%name)
            return
        end if
        if (size(occs) > def%kws(k)%max .or. size(occs) == 0) then
            call set_error(st, STATUS_DECK_ERROR, 'expected ' // count_text(1, &
                def%kws(k)%max) // ' occurrence(s) of _F(...), got ' // to_text(size(occs)), &
                file=file, line=line, column=col, command=def%name, keyword=def%kws(k)%name)
            return
        end if
        allocate (factor%occ(size(occs)))
        do i = 1, size(occs)
            if (occs(i)%kind /= VK_FACTOR) then
                call set_error(st, STATUS_DECK_ERROR, 'expected _F(...), got ' // &
                    kind_label(occs(i)), file=file, line=vline(occs(i), line), &
                    column=vcol(occs(i), col), command=def%name, keyword=def%kws(k)%name)
                return
            end if
            associate (occ => factor%occ(i))
                occ%file = file; occ%command = def%name; occ%scope = def%kws(k)%name
                occ%line = vline(occs(i), line); occ%col = vcol(occs(i), col)
                allocate (occ%items(8))
                list = unpack_value(occs(i))
                active = active_blocs(def, k, list)
                call check_scope(def, k, list, active, file, st)
                if (st%failed()) return
                do j = 1, size(list%keys)
                    kw = find_active(def, k, list%keys(j)%s, active)
                    call add_simple(def, kw, list, j, file, occ, st)
                    if (st%failed()) return
                end do
                call check_required(def, k, list, active, file, occ%line, occ%col, st)
                if (st%failed()) return
                call fill_defaults(def, k, active, occ)
            end associate
        end do
    end subroutine build_factor

    !> Checks and normalizes argument j of `args` against keyword kw (0: open keyword).
    subroutine add_simple(def, kw, args, j, file, set, st)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: kw, j
        type(value_list_t), intent(in) :: args
        character(len=*), intent(in) :: file
        class(keyword_set_t), intent(inout) :: set
        type(status_t), intent(inout) :: st
        type(kw_value_t) :: item
        type(value_t), allocatable :: items(:)
        type(value_list_t) :: list
        integer :: i, parent
        character(len=:), allocatable :: msg
        item%name = args%keys(j)%s
        item%line = args%key_line(j); item%col = args%key_col(j)
        item%value = args%items(j)
        if (kw == 0) then                       ! open keyword (FORMULE binds objects)
            call set%add(item)
            return
        end if
        parent = def%kws(kw)%parent
        associate (k => def%kws(kw), v => args%items(j))
            if (k%types == 'ANY') then         ! bookkeeping keyword: anything goes
                call set%add(item)
                return
            end if
            if (v%kind == VK_FACTOR) then
                call fail(v, 'expected ' // type_words(k%types) // ', got _F(...) (this ' // &
                          'keyword is not a factor keyword)'); return
            end if
            if (v%kind == VK_TUPLE .or. v%kind == VK_LIST) then
                list = unpack_value(v)
                items = list%items
            else
                allocate (items(1))
                items(1) = v
            end if
            if (size(items) < k%min .or. size(items) > k%max) then
                call fail(v, 'expected ' // count_text(k%min, k%max) // ' value(s), got ' // &
                          to_text(size(items))); return
            end if
            do i = 1, size(items)
                if (.not. type_accepts(k%types, items(i))) then
                    call fail(items(i), 'expected ' // type_words(k%types) // ', got ' // &
                              describe(items(i))); return
                end if
                if (index(k%types, 'R') == 1 .and. items(i)%kind /= VK_REAL .and. &
                    is_number(items(i))) items(i) = real_value(as_real(items(i)))
                if (size(k%into) > 0) then
                    msg = check_into(k, items(i))
                    if (len(msg) > 0) then
                        call fail(items(i), msg); return
                    end if
                end if
                msg = check_range(k, items(i))
                if (len(msg) > 0) then
                    call fail(items(i), msg); return
                end if
            end do
            if (k%max == 1) then
                item%value = items(1)
            else
                item%value = sequence_value(VK_TUPLE, items)
            end if
        end associate
        call set%add(item)
    contains
        subroutine fail(where, message)
            type(value_t), intent(in) :: where
            character(len=*), intent(in) :: message
            call set_error(st, STATUS_DECK_ERROR, message, file=file, &
                line=vline(where, args%key_line(j)), column=vcol(where, args%key_col(j)), &
                command=def%name, keyword=path(def, parent, args%keys(j)%s))
        end subroutine fail
    end subroutine add_simple

    !> '' when v is a number inside kw's range (or kw has none), else the message naming
    !> the value and the range.
    function check_range(kw, v) result(msg)
        type(kw_def_t), intent(in) :: kw
        type(value_t), intent(in) :: v
        character(len=:), allocatable :: msg
        real(dp) :: x
        msg = ''
        if (.not. (kw%has_vmin .or. kw%has_vmax .or. kw%has_vtiny) .or. &
            .not. is_number(v)) return
        x = as_real(v)
        if (kw%has_vtiny .and. abs(x) > 0.0_dp .and. abs(x) < kw%vtiny) then
            msg = 'value ' // value_text(v) // ' is too small: ' // kw%name // ' is 0 or at ' &
                // 'least ' // range_bound(kw%vtiny) // ' in magnitude (its inverse must ' // &
                'stay finite)'
            return
        end if
        if (.not. (kw%has_vmin .or. kw%has_vmax)) return
        if (kw%has_vmin .and. kw%has_vmax) then
            if (x < kw%vmin .or. x > kw%vmax) msg = 'value ' // value_text(v) // &
                ' is out of range (' // range_bound(kw%vmin) // ' <= ' // kw%name // ' <= ' &
                // range_bound(kw%vmax) // ')'
        else if (kw%has_vmin) then
            if (x < kw%vmin) msg = 'value ' // value_text(v) // ' is out of range (' // &
                kw%name // ' >= ' // range_bound(kw%vmin) // ')'
        else
            if (x > kw%vmax) msg = 'value ' // value_text(v) // ' is out of range (' // &
                kw%name // ' <= ' // range_bound(kw%vmax) // ')'
        end if
    end function check_range

    ! A bound as the deck would write it: 0, -1, 0.5, 1E+30, 2.5E-07, 1000000000.
    function range_bound(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=40) :: buf
        integer :: e, k
        if (abs(x) < 1.0e10_dp .and. same_real(x, aint(x))) then
            write (buf, '(i0)') int(x, i8)
            text = trim(buf)
        else if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e10_dp) then
            write (buf, '(f25.12)') x
            text = strip_zeros(trim(adjustl(buf)))
        else
            write (buf, '(es14.6e3)') x
            buf = adjustl(buf)
            e = index(buf, 'E')
            read (buf(e + 1:), *) k
            text = strip_zeros(buf(1:e - 1))
            write (buf, '(i0)') abs(k)
            if (abs(k) < 10) text = text // 'E' // merge('-', '+', k < 0) // '0' // trim(buf)
            if (abs(k) >= 10) text = text // 'E' // merge('-', '+', k < 0) // trim(buf)
        end if
    end function range_bound

    ! 1.500000 -> 1.5, 2.000 -> 2
    pure function strip_zeros(number) result(text)
        character(len=*), intent(in) :: number
        character(len=:), allocatable :: text
        integer :: k
        k = len(number)
        if (index(number, '.') > 0) then
            do while (k > 1 .and. number(k:k) == '0')
                k = k - 1
            end do
            if (number(k:k) == '.') k = k - 1
        end if
        text = number(1:k)
    end function strip_zeros

    !> '' when v is one of kw%into, else the message.
    function check_into(kw, v) result(msg)
        type(kw_def_t), intent(in) :: kw
        type(value_t), intent(in) :: v
        character(len=:), allocatable :: msg, text
        integer :: i
        msg = ''
        if (v%kind == VK_STR) then
            text = v%s
        else if (v%kind == VK_INT) then
            text = to_text(v%i)
        else
            return
        end if
        do i = 1, size(kw%into)
            if (kw%into(i)%s == text) return
        end do
        msg = 'value ' // value_text(v) // ' is not allowed' // did_you_mean(text, kw%into) // &
              ' (allowed: ' // join_words(kw%into, ', ') // ')'
    end function check_into

    !> Adds catalog defaults for keywords of scope `parent` that were not given (those of
    !> active blocks and outside blocks).
    subroutine fill_defaults(def, parent, active, set)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        logical, intent(in) :: active(:)
        class(keyword_set_t), intent(inout) :: set
        integer :: k
        type(kw_value_t) :: item
        do k = 1, def%nkw
            associate (kw => def%kws(k))
                if (kw%parent /= parent .or. kw%is_factor .or. len(kw%default) == 0) cycle
                if (.not. in_force(kw%bloc, active)) cycle
                if (set%has(kw%name)) cycle
                item%name = kw%name
                item%value = default_value(kw)
                item%is_default = .true.
                call set%add(item)
            end associate
        end do
    end subroutine fill_defaults

    !> The catalog default of a keyword as a value (blank-separated words for lists).
    function default_value(kw) result(v)
        type(kw_def_t), intent(in) :: kw
        type(value_t) :: v
        type(string_t), allocatable :: words(:)
        type(value_t), allocatable :: items(:)
        integer :: i
        call split_words(kw%default, words)
        allocate (items(size(words)))
        do i = 1, size(words)
            select case (kw%types(1:1))
            case ('I')
                items(i) = int_value(parse_int(words(i)%s))
            case ('R')
                items(i) = real_value(parse_real(words(i)%s))
            case default
                items(i) = str_value(words(i)%s)
            end select
        end do
        if (kw%max == 1) then
            v = items(1)
        else
            v = sequence_value(VK_TUPLE, items)
        end if
    end function default_value

    !> True when value v is acceptable for the '|'-separated catalog types.
    logical function type_accepts(types, v)
        character(len=*), intent(in) :: types
        type(value_t), intent(in) :: v
        type(string_t), allocatable :: words(:)
        integer :: i
        type_accepts = .false.
        call split_words(expand_types(types), words)
        do i = 1, size(words)
            select case (words(i)%s)
            case ('ANY')
                type_accepts = .true.
            case ('I')
                type_accepts = v%kind == VK_INT .or. v%kind == VK_BOOL
            case ('R')
                type_accepts = is_number(v)
            case ('TXM')
                type_accepts = v%kind == VK_STR
            case ('assd')                        ! Code_Aster's base of every concept
                type_accepts = v%kind == VK_CONCEPT
            case ('CO')                          ! a concept the command makes: CO('NAME')
                type_accepts = v%kind == VK_CO
            case default
                ! 'unknown': a check-pass placeholder for a CO('NAME') output, whose type is
                ! known when the command runs
                if (v%kind == VK_CONCEPT) type_accepts = v%s == words(i)%s .or. &
                    v%s == 'unknown'
            end select
            if (type_accepts) return
        end do
    end function type_accepts

    !> 'FUNC|R' -> 'fonction formule R' (blank-separated concrete types).
    function expand_types(types) result(out)
        character(len=*), intent(in) :: types
        character(len=:), allocatable :: out
        type(string_t), allocatable :: words(:)
        integer :: i
        character(len=len(types)) :: t
        t = types
        do i = 1, len(t)
            if (t(i:i) == '|') t(i:i) = ' '
        end do
        call split_words(t, words)
        out = ''
        do i = 1, size(words)
            select case (words(i)%s)
            case ('FUNC')
                out = out // ' fonction formule'
            case ('RESU', '@TYPE_RESU', '@RESULTAT')
                out = out // ' evol_elas evol_noli evol_ther evol_sech evol_varc evol_char'
            case ('CHAM_GD', '@TYPE_CHAM')   ! Code_Aster's cham_gd_sdaster: any field
                out = out // ' cham_no_sdaster cham_elem carte_sdaster'
            case default
                out = out // ' ' // words(i)%s
            end select
        end do
    end function expand_types

    !> Catalog types in words: 'a real', 'a text', 'a concept of type fonction or formule'.
    function type_words(types) result(text)
        character(len=*), intent(in) :: types
        character(len=:), allocatable :: text
        type(string_t), allocatable :: words(:)
        character(len=:), allocatable :: concepts
        integer :: i
        call split_words(expand_types(types), words)
        text = ''
        concepts = ''
        do i = 1, size(words)
            select case (words(i)%s)
            case ('I')
                text = text // ' or an integer'
            case ('R')
                text = text // ' or a real'
            case ('TXM')
                text = text // ' or a text'
            case ('assd')
                text = text // ' or a concept'
            case ('CO')
                text = text // " or the name of a concept to make, CO('NAME')"
            case default
                if (len(concepts) > 0) concepts = concepts // ' or '
                concepts = concepts // words(i)%s
            end select
        end do
        if (len(concepts) > 0) text = text // ' or a concept of type ' // concepts
        text = text(5:)
    end function type_words

    function describe(v) result(text)
        type(value_t), intent(in) :: v
        character(len=:), allocatable :: text
        text = kind_label(v)
        select case (v%kind)
        case (VK_STR, VK_INT, VK_REAL)
            text = text // ' ' // value_text(v)
        case (VK_CONCEPT)
            if (associated(v%obj)) then
                if (allocated(v%obj%name)) then
                    if (len(v%obj%name) > 0) text = text // ' (' // v%obj%name // ')'
                end if
            end if
        end select
    end function describe

    function count_text(lo, hi) result(text)
        integer, intent(in) :: lo, hi
        character(len=:), allocatable :: text
        if (hi == MANY) then
            text = 'at least ' // to_text(lo)
        else if (lo == hi) then
            text = to_text(lo)
        else
            text = 'between ' // to_text(lo) // ' and ' // to_text(hi)
        end if
    end function count_text

    ! The keywords in force in a scope (outside blocks or in active ones), each once.
    function scope_names(def, parent, active) result(names)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        logical, intent(in) :: active(:)
        type(string_t), allocatable :: names(:)
        integer :: k, i
        allocate (names(0))
        do k = 1, def%nkw
            if (def%kws(k)%parent /= parent .or. .not. in_force(def%kws(k)%bloc, active)) cycle
            if (any([(names(i)%s == def%kws(k)%name, i = 1, size(names))])) cycle
            call append_string(names, def%kws(k)%name)
        end do
    end function scope_names

    function path(def, parent, name) result(text)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        text = name
        if (parent > 0) text = def%kws(parent)%name // '/' // name
    end function path

    function scope_path(def, parent) result(text)
        type(cmd_def_t), intent(in) :: def
        integer, intent(in) :: parent
        character(len=:), allocatable :: text
        text = ''
        if (parent > 0) text = def%kws(parent)%name
    end function scope_path

    logical function given(args, name)
        type(value_list_t), intent(in) :: args
        character(len=*), intent(in) :: name
        integer :: j
        given = .false.
        do j = 1, size(args%keys)
            if (args%keys(j)%s == name) given = .true.
        end do
    end function given

    integer function key_line(args, name)
        type(value_list_t), intent(in) :: args
        character(len=*), intent(in) :: name
        integer :: j
        key_line = 0
        do j = 1, size(args%keys)
            if (args%keys(j)%s == name) key_line = args%key_line(j)
        end do
    end function key_line

    integer function key_col(args, name)
        type(value_list_t), intent(in) :: args
        character(len=*), intent(in) :: name
        integer :: j
        key_col = 0
        do j = 1, size(args%keys)
            if (args%keys(j)%s == name) key_col = args%key_col(j)
        end do
    end function key_col

    integer function vline(v, fallback)
        type(value_t), intent(in) :: v
        integer, intent(in) :: fallback
        vline = v%line
        if (vline == 0) vline = fallback
    end function vline

    integer function vcol(v, fallback)
        type(value_t), intent(in) :: v
        integer, intent(in) :: fallback
        vcol = v%col
        if (v%line == 0) vcol = fallback
    end function vcol

    integer(i8) function parse_int(text)
        character(len=*), intent(in) :: text
        read (text, *) parse_int
    end function parse_int

    real(dp) function parse_real(text)
        character(len=*), intent(in) :: text
        read (text, *) parse_real
    end function parse_real

end module deck_validate
