!> The deck evaluator (deck_interpreter), Code_Aster's user macros (doc/deck-language.md,
!> "User macros"): a module of the deck defines a command of its own as Code_Aster's
!> code_aster.Cata.Syntax and code_aster.Supervis.ExecuteCommand let it,
!>     CATA = MACRO(nom="CHAR_ROTA", op=char_rota_ops, sd_prod=char_meca,
!>                  MODELE=SIMP(statut="o", typ=modele_sdaster), ...)
!>     CHAR_ROTA = UserMacro("CHAR_ROTA", CATA, char_rota_ops)
!> SIMP, FACT and the rules (EXCLUS, UN_PARMI, AU_MOINS_UN, PRESENT_PRESENT, PRESENT_ABSENT,
!> ENSEMBLE) describe its keywords as Code_Aster's catalog does; UserMacro turns the MACRO
!> into an entry of the run's catalog of user macros (ctx%user_macros), so that a call is
!> validated as a built-in command is (unknown keywords, types, cardinality, into,
!> val_min/val_max, statut "o", rules, defaults: deck_validate). A call then runs
!> op(self, **keywords) with the defaults filled in, as Code_Aster's ExecuteMacro does
!> (self is None: parasol has no macro object), and gives what op returns, which must be a
!> concept of type sd_prod when sd_prod is a type.
!>
!> Values: SIMP(...) and FACT(...) are _F values tagged 'SIMP' / 'FACT' (value%s), a rule a
!> tuple tagged 'RULE:NAME', MACRO(...) a _F tagged 'MACRO', a user macro a _F tagged
!> 'UserMacro' holding its name and op. Code_Aster's data structure types
!> (code_aster.Cata.DataStructure: modele_sdaster, char_meca, ...) are the stand-ins the
!> import binds (deck_interp_imports), read here as concept types.
submodule(deck_interpreter) deck_interp_macros
    use deck_catalog, only: catalog_t, MANY, RULE_EXCLUS, RULE_UN_PARMI, RULE_AU_MOINS_UN, &
        RULE_PRESENT_PRESENT, RULE_PRESENT_ABSENT, RULE_ENSEMBLE
    use deck_validate, only: validate_command, type_accepts
    use deck_command, only: command_t, keyword_set_t
    implicit none

    !> MACRO's own arguments (Code_Aster's MACRO attributes); the others are keywords.
    character(len=*), parameter :: MACRO_ATTRIBUTES = ' nom op sd_prod reentrant fr ang ' // &
        'docu UIinfo regles compat_syntax '
    !> SIMP's arguments: those parasol's catalog uses, then those that only document
    !> (Code_Aster's fr, ang, validators, position ...: no effect on validation here).
    character(len=*), parameter :: SIMP_ARGUMENTS = 'statut typ defaut into max min ' // &
        'val_min val_max fr ang validators position sug homo inout docu'
    character(len=*), parameter :: FACT_ARGUMENTS = ' statut max min fr ang regles docu '
    character(len=*), parameter :: DATA_STRUCTURE = 'code_aster.Cata.DataStructure.'

contains

    !> SIMP(...), FACT(...), MACRO(...), the rules, UserMacro(name, cata, op).
    module procedure cata_builtin
        type(value_t) :: x
        logical :: found
        integer :: k
        select case (name)
        case ('Cata.SIMP')
            call arity(ctx, id, 'SIMP', args, kwargs, 0, 0, SIMP_ARGUMENTS, st)
            if (st%failed()) return
            call kwarg(kwargs, 'typ', x, found)
            if (.not. found) then
                call fail(st, ctx, id, 'SIMP() needs typ= (the type of the keyword''s ' // &
                          'values: "R", "I", "TXM" or a data structure type)'); return
            end if
            call check_statut(kwargs)
            if (st%failed()) return
            v = kwargs
            v%s = 'SIMP'
        case ('Cata.FACT')
            if (size(args) > 0) then
                call fail(st, ctx, id, 'FACT() takes keyword arguments only'); return
            end if
            call check_statut(kwargs)
            if (st%failed()) return
            v = kwargs
            v%s = 'FACT'
        case ('Cata.MACRO')
            if (size(args) > 0) then
                call fail(st, ctx, id, 'MACRO() takes keyword arguments only'); return
            end if
            do k = 1, 2
                call kwarg(kwargs, trim(merge('nom', 'op ', k == 1)), x, found)
                if (.not. found) then
                    call fail(st, ctx, id, 'MACRO() needs ' // trim(merge('nom', 'op ', &
                              k == 1)) // '='); return
                end if
            end do
            call kwarg(kwargs, 'nom', x, found)
            if (.not. want_text(ctx, id, x, 'MACRO(nom=)', st)) return
            v = kwargs
            v%s = 'MACRO'
        case ('Cata.UserMacro')
            call arity(ctx, id, 'UserMacro', args, kwargs, 3, 3, '', st)
            if (st%failed()) return
            if (.not. want_text(ctx, id, args(1), 'UserMacro(name, cata, op): name', st)) &
                return
            if (args(2)%kind /= VK_FACTOR .or. .not. tagged(args(2), 'MACRO')) then
                call fail(st, ctx, id, 'UserMacro(name, cata, op): cata must be a ' // &
                          'MACRO(...), got ' // kind_label(args(2))); return
            end if
            if (args(3)%kind /= VK_DEF) then
                call fail(st, ctx, id, 'UserMacro(name, cata, op): op must be a def ' // &
                          'function, got ' // kind_label(args(3))); return
            end if
            call describe_macro(ctx, id, args(1)%s, args(2), st)
            if (st%failed()) return
            v = sequence_value(VK_FACTOR, values_of(args(1), args(3)))
            v%s = 'UserMacro'
        case default
            ! the rules: EXCLUS("A", "B"), ... (names of keywords of the scope)
            do k = 1, size(args)
                if (.not. want_text(ctx, id, args(k), name(6:) // '()', st)) return
            end do
            if (size(args) < 2) then
                call fail(st, ctx, id, name(6:) // '() takes the names of two keywords ' // &
                          'or more'); return
            end if
            call only_kwargs(ctx, id, name(6:) // '()', kwargs, '', st)
            if (st%failed()) return
            v = sequence_value(VK_TUPLE, args)
            v%s = 'RULE:' // name(6:)
        end select
    contains
        subroutine check_statut(kw)
            type(value_t), intent(in) :: kw
            type(value_t) :: s
            logical :: given
            call kwarg(kw, 'statut', s, given)
            if (.not. given) return
            if (s%kind == VK_STR) then
                if (index(' o f c d ', ' ' // s%s // ' ') > 0 .and. len(s%s) == 1) return
            end if
            call fail(st, ctx, id, name(6:) // '(statut=...): "o" (mandatory), "f" ' // &
                      '(optional), "c" or "d", got ' // text_of(ctx, s, .true.))
        end subroutine check_statut
    end procedure cata_builtin

    !> True when v carries tag `tag` (value%s).
    pure logical function tagged(v, tag)
        type(value_t), intent(in) :: v
        character(len=*), intent(in) :: tag
        tagged = .false.
        if (allocated(v%s)) tagged = v%s == tag
    end function tagged

    !> Adds (or replaces) user macro `name` in ctx%user_macros from its MACRO(...) value.
    subroutine describe_macro(ctx, id, name, macro, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: macro
        type(status_t), intent(inout) :: st
        type(catalog_t) :: c
        type(value_list_t) :: list
        type(value_t) :: flat, sd_prod
        character(len=:), allocatable :: message, result_type
        logical :: found
        integer :: k, old
        call ctx%heap%flatten(macro, flat, message)
        if (len(message) > 0) then
            call fail(st, ctx, id, 'MACRO: ' // message); return
        end if
        result_type = ''
        call kwarg(flat, 'sd_prod', sd_prod, found)
        if (found .and. sd_prod%kind /= VK_NONE .and. sd_prod%kind /= VK_DEF) then
            ! a type (a function of the keywords, Code_Aster's other form, is not checked)
            result_type = data_type(sd_prod)
            if (len(result_type) == 0) then
                call fail(st, ctx, id, 'MACRO(sd_prod=...): a data structure type ' // &
                    '(code_aster.Cata.DataStructure), got ' // text_of(ctx, sd_prod, .true.))
                return
            end if
        end if
        call c%command(name, result_type)
        list = unpack_value(flat)
        do k = 1, size(list%keys)
            if (index(MACRO_ATTRIBUTES, ' ' // list%keys(k)%s // ' ') > 0) cycle
            call add_keyword(c, list%keys(k)%s, list%items(k), .false.)
            if (st%failed()) return
        end do
        do k = 1, size(list%keys)
            if (list%keys(k)%s == 'regles') call add_rules(c, list%items(k))
            if (st%failed()) return
        end do
        ! the macro's entry replaces one of the same name (a module run in both passes, or
        ! a macro defined anew)
        old = ctx%user_macros%find_command(name)
        if (old == 0) then
            call ctx%user_macros%command(name, result_type)
            old = ctx%user_macros%ncmd
        end if
        ctx%user_macros%cmds(old) = c%cmds(1)
    contains
        !> A keyword of the macro (or of a FACT): SIMP or FACT.
        recursive subroutine add_keyword(cat, key, kv, in_factor)
            type(catalog_t), intent(inout) :: cat
            character(len=*), intent(in) :: key
            type(value_t), intent(in) :: kv
            logical, intent(in) :: in_factor
            type(value_list_t) :: inner
            integer :: j
            if (kv%kind == VK_FACTOR .and. tagged(kv, 'SIMP')) then
                call add_simple(cat, key, kv)
            else if (kv%kind == VK_FACTOR .and. tagged(kv, 'FACT')) then
                if (in_factor) then
                    call fail(st, ctx, id, 'MACRO: ' // key // '=FACT(...) inside a FACT ' // &
                              '(Code_Aster''s factor keywords hold simple keywords only)')
                    return
                end if
                call cat%fact(key, max=max_of(kv, 1), req=statut_of(kv) == 'o')
                inner = unpack_value(kv)
                do j = 1, size(inner%keys)
                    if (index(FACT_ARGUMENTS, ' ' // inner%keys(j)%s // ' ') > 0) cycle
                    call add_keyword(cat, inner%keys(j)%s, inner%items(j), .true.)
                    if (st%failed()) return
                end do
                do j = 1, size(inner%keys)
                    if (inner%keys(j)%s == 'regles') call add_rules(cat, inner%items(j))
                    if (st%failed()) return
                end do
                call cat%end_fact()
            else
                call fail(st, ctx, id, 'MACRO: ' // key // '= must be SIMP(...) or ' // &
                    'FACT(...) (a keyword of the macro), got ' // kind_label(kv) // &
                    ' (MACRO''s own arguments:' // MACRO_ATTRIBUTES // ')')
            end if
        end subroutine add_keyword

        !> A SIMP: types, cardinality, statut, default, into, val_min / val_max.
        subroutine add_simple(cat, key, kv)
            type(catalog_t), intent(inout) :: cat
            character(len=*), intent(in) :: key
            type(value_t), intent(in) :: kv
            type(value_t) :: typ, x
            type(value_list_t) :: parts
            character(len=:), allocatable :: types, def_text, into_text, one
            logical :: has_def, has_into, has_min, has_max, has_typ
            real(dp) :: vmin, vmax
            integer :: j
            call kwarg(kv, 'typ', typ, has_typ)
            types = ''
            one = ''
            if (typ%kind == VK_TUPLE .or. typ%kind == VK_LIST) then
                parts = unpack_value(typ)
                do j = 1, size(parts%items)
                    one = simple_type(parts%items(j))
                    if (len(one) == 0) exit
                    types = types // merge('|', ' ', len(types) > 0) // one
                end do
                if (len(types) > 0) types = trim(adjustl(types))
            else
                one = simple_type(typ)
                types = one
            end if
            if (len(one) == 0) then
                call fail(st, ctx, id, 'MACRO: ' // key // '=SIMP(typ=...): "R", "I", ' // &
                    '"TXM" (or "K8", "K16", "K24") or a data structure type ' // &
                    '(code_aster.Cata.DataStructure), got ' // text_of(ctx, typ, .true.))
                return
            end if
            call kwarg(kv, 'defaut', x, has_def)
            def_text = ''
            if (has_def) then
                ! Code_Aster checks a default against typ when the catalog is built
                if (x%kind == VK_TUPLE .or. x%kind == VK_LIST) then
                    parts = unpack_value(x)
                else
                    if (allocated(parts%items)) deallocate (parts%items)
                    allocate (parts%items(1))
                    parts%items(1) = x
                end if
                do j = 1, size(parts%items)
                    if (.not. type_accepts(types, parts%items(j)) .or. &
                        parts%items(j)%kind == VK_CONCEPT) then
                        call fail(st, ctx, id, 'MACRO: ' // key // '=SIMP(defaut=' // &
                            text_of(ctx, parts%items(j), .true.) // '): not a value of ' // &
                            'its typ (' // types // ')'); return
                    end if
                end do
                def_text = words_of(x)
            end if
            call kwarg(kv, 'into', x, has_into)
            into_text = ''
            if (has_into) into_text = words_of(x)
            call kwarg(kv, 'val_min', x, has_min)
            vmin = 0.0_dp
            if (has_min .and. is_number(x)) vmin = as_real(x)
            has_min = has_min .and. is_number(x)
            call kwarg(kv, 'val_max', x, has_max)
            vmax = 0.0_dp
            if (has_max .and. is_number(x)) vmax = as_real(x)
            has_max = has_max .and. is_number(x)
            if (min_of(kv) > max_of(kv, 1)) then
                call fail(st, ctx, id, 'MACRO: ' // key // '=SIMP(min=..., max=...): min ' // &
                          'is above max'); return
            end if
            if (has_min .and. has_max) then
                call cat%key(key, types, min=min_of(kv), max=max_of(kv, 1), &
                    req=statut_of(kv) == 'o', def=def_text, into=into_text, vmin=vmin, &
                    vmax=vmax)
            else if (has_min) then
                call cat%key(key, types, min=min_of(kv), max=max_of(kv, 1), &
                    req=statut_of(kv) == 'o', def=def_text, into=into_text, vmin=vmin)
            else if (has_max) then
                call cat%key(key, types, min=min_of(kv), max=max_of(kv, 1), &
                    req=statut_of(kv) == 'o', def=def_text, into=into_text, vmax=vmax)
            else
                call cat%key(key, types, min=min_of(kv), max=max_of(kv, 1), &
                    req=statut_of(kv) == 'o', def=def_text, into=into_text)
            end if
        end subroutine add_simple

        !> regles=(EXCLUS(...), ...) in the scope being described.
        subroutine add_rules(cat, rv)
            type(catalog_t), intent(inout) :: cat
            type(value_t), intent(in) :: rv
            type(value_list_t) :: rules, names
            character(len=:), allocatable :: text
            integer :: j, i, kind
            if (rule_kind(rv) > 0) then
                allocate (rules%items(1))
                rules%items(1) = rv
            else if (rv%kind == VK_TUPLE .or. rv%kind == VK_LIST) then
                rules = unpack_value(rv)
            else
                allocate (rules%items(1))
                rules%items(1) = rv
            end if
            do j = 1, size(rules%items)
                kind = rule_kind(rules%items(j))
                if (kind == 0) then
                    call fail(st, ctx, id, 'MACRO(regles=...): EXCLUS, UN_PARMI, ' // &
                        'AU_MOINS_UN, PRESENT_PRESENT, PRESENT_ABSENT or ENSEMBLE ' // &
                        '(from code_aster.Cata.Syntax), got ' // &
                        text_of(ctx, rules%items(j), .true.)); return
                end if
                names = unpack_value(rules%items(j))
                text = ''
                do i = 1, size(names%items)
                    text = text // ' ' // names%items(i)%s
                end do
                call cat%rule(kind, text)
            end do
        end subroutine add_rules
    end subroutine describe_macro

    !> The rule kind of a RULE:NAME tuple, 0 if v is not one.
    pure integer function rule_kind(v)
        type(value_t), intent(in) :: v
        rule_kind = 0
        if (v%kind /= VK_TUPLE .or. .not. allocated(v%s)) return
        select case (v%s)
        case ('RULE:EXCLUS')
            rule_kind = RULE_EXCLUS
        case ('RULE:UN_PARMI')
            rule_kind = RULE_UN_PARMI
        case ('RULE:AU_MOINS_UN')
            rule_kind = RULE_AU_MOINS_UN
        case ('RULE:PRESENT_PRESENT')
            rule_kind = RULE_PRESENT_PRESENT
        case ('RULE:PRESENT_ABSENT')
            rule_kind = RULE_PRESENT_ABSENT
        case ('RULE:ENSEMBLE')
            rule_kind = RULE_ENSEMBLE
        end select
    end function rule_kind

    !> statut= of a SIMP or FACT ('f' when not given, as Code_Aster's default).
    function statut_of(kv) result(s)
        type(value_t), intent(in) :: kv
        character(len=:), allocatable :: s
        type(value_t) :: x
        logical :: found
        s = 'f'
        call kwarg(kv, 'statut', x, found)
        if (found .and. x%kind == VK_STR) s = x%s
    end function statut_of

    !> max= ('**' = any number); `otherwise` when not given.
    integer function max_of(kv, otherwise)
        type(value_t), intent(in) :: kv
        integer, intent(in) :: otherwise
        type(value_t) :: x
        logical :: found
        max_of = otherwise
        call kwarg(kv, 'max', x, found)
        if (.not. found) return
        if (x%kind == VK_STR) then
            if (x%s == '**') max_of = MANY
        else if (x%kind == VK_INT) then
            max_of = int(max(1_i8, min(x%i, int(MANY, i8))))
        end if
    end function max_of

    integer function min_of(kv)
        type(value_t), intent(in) :: kv
        type(value_t) :: x
        logical :: found
        min_of = 1
        call kwarg(kv, 'min', x, found)
        if (found .and. x%kind == VK_INT) min_of = int(max(0_i8, min(x%i, 1000000_i8)))
    end function min_of

    !> A SIMP's typ in parasol's catalog words ('' when not one).
    function simple_type(t) result(word)
        type(value_t), intent(in) :: t
        character(len=:), allocatable :: word
        word = ''
        if (t%kind == VK_STR) then
            select case (t%s)
            case ('R', 'I', 'TXM')
                word = t%s
            case ('K8', 'K16', 'K24', 'K80')
                word = 'TXM'
            end select
            return
        end if
        word = data_type(t)
    end function simple_type

    !> Code_Aster's data structure type (a stand-in of code_aster.Cata.DataStructure) as
    !> parasol's concept type words ('' when v is not one).
    function data_type(v) result(word)
        type(value_t), intent(in) :: v
        character(len=:), allocatable :: word
        character(len=:), allocatable :: ds
        word = ''
        if (v%kind /= VK_MODULE .or. .not. allocated(v%s)) return
        if (index(v%s, DATA_STRUCTURE) /= 1) return
        ds = v%s(len(DATA_STRUCTURE) + 1:)
        select case (ds)
        case ('resultat_sdaster')
            word = 'RESU'
        case ('cham_gd_sdaster')
            word = 'CHAM_GD'
        case ('assd')
            word = 'assd'
        case ('cham_no_sdaster', 'carte_sdaster', 'table_sdaster')
            word = ds
        case default
            word = ds
            if (len(ds) > 8) then
                if (ds(len(ds) - 7:) == '_sdaster') word = ds(1:len(ds) - 8)
            end if
        end select
    end function data_type

    !> A default or into= as the catalog's blank-separated words.
    function words_of(x) result(text)
        type(value_t), intent(in) :: x
        character(len=:), allocatable :: text
        type(value_list_t) :: parts
        integer :: j
        if (x%kind == VK_TUPLE .or. x%kind == VK_LIST) then     ! flat: describe_macro
            parts = unpack_value(x)
            text = ''
            do j = 1, size(parts%items)
                text = text // ' ' // word(parts%items(j))
            end do
            text = trim(adjustl(text))
        else
            text = word(x)
        end if
    contains
        function word(y) result(w)
            type(value_t), intent(in) :: y
            character(len=:), allocatable :: w
            character(len=32) :: buf
            select case (y%kind)
            case (VK_INT)
                w = to_text(y%i)
            case (VK_REAL)
                write (buf, '(es25.17e3)') y%r
                w = trim(adjustl(buf))
            case (VK_STR)
                w = y%s
            case default
                w = value_text(y)
            end select
        end function word
    end function words_of

    !> NAME(**keywords) of a user macro: validated against its catalog entry, then its op
    !> called with the keywords and defaults (factor keywords as _F, or tuples of _F when
    !> max > 1, as Code_Aster gives them).
    module procedure call_user_macro
        type(value_t) :: name, op, flat, keywords
        type(value_t), allocatable :: self(:)
        type(command_t) :: cmd
        type(value_list_t) :: kw
        character(len=:), allocatable :: message
        integer :: icmd, k, j, n
        name = item(f, 1)
        op = item(f, 2)
        if (size(args) > 0) then
            call fail(st, ctx, id, name%s // ' takes keyword arguments only (KEYWORD=value)')
            return
        end if
        icmd = ctx%user_macros%find_command(name%s)
        if (icmd == 0) then
            call fail(st, ctx, id, 'user macro ' // name%s // ' is not defined in this ' // &
                      'session'); return
        end if
        if (ctx%checking .and. holds_unknown(kwargs)) then
            v%kind = VK_UNKNOWN; return                ! validated when the deck runs
        end if
        call ctx%heap%flatten(kwargs, flat, message)
        if (len(message) > 0) then
            call fail(st, ctx, id, name%s // ': ' // message); return
        end if
        call validate_command(ctx%user_macros, icmd, flat, node_file(ctx, id), &
            int(ctx%ast%nodes(id)%line), int(ctx%ast%nodes(id)%col), cmd, st)
        if (st%failed()) return
        ! the keywords op receives: those given, the defaults, the factor keywords
        allocate (kw%items(0), kw%keys(0), kw%key_line(0), kw%key_col(0))
        do k = 1, cmd%n
            call add(cmd%items(k)%name, cmd%items(k)%value)
        end do
        do k = 1, cmd%nfactor
            n = size(cmd%factors(k)%occ)
            block
                type(value_t), allocatable :: occs(:)
                allocate (occs(n))
                do j = 1, n
                    occs(j) = occurrence_value(cmd%factors(k)%occ(j))
                end do
                if (factor_max(cmd%factors(k)%name) == 1 .and. n == 1) then
                    call add(cmd%factors(k)%name, occs(1))
                else
                    call add(cmd%factors(k)%name, sequence_value(VK_TUPLE, occs))
                end if
            end block
        end do
        keywords = pack_values(VK_FACTOR, kw)
        if (.not. ctx%checking) call ctx%write_mess('  -- user macro ' // name%s // &
            ' (' // node_where(ctx, id) // '): ' // op%s // '(self, **keywords)')
        allocate (self(1))
        self(1)%kind = VK_NONE
        call call_value(ctx, id, op, self, keywords, v, st, frame)
        if (st%failed()) return
        associate (rtype => ctx%user_macros%cmds(icmd)%result_type)
            if (len(rtype) == 0 .or. v%kind == VK_UNKNOWN) return
            if (v%kind == VK_CONCEPT) then
                if (type_accepts(rtype, v)) return
            end if
            message = kind_label(v)
            if (v%kind == VK_CONCEPT .and. allocated(v%s)) message = message // ' of type ' // v%s
            call fail(st, ctx, id, name%s // ': its op ' // op%s // ' returned ' // message // &
                      ', not a concept of type ' // rtype // ' (MACRO(sd_prod=...))')
        end associate
    contains
        subroutine add(key, value)
            character(len=*), intent(in) :: key
            type(value_t), intent(in) :: value
            call append_value(kw%items, value)
            call append_string(kw%keys, key)
            kw%key_line = [kw%key_line, 0]
            kw%key_col = [kw%key_col, 0]
        end subroutine add

        function occurrence_value(occ) result(ov)
            type(keyword_set_t), intent(in) :: occ
            type(value_t) :: ov
            type(value_list_t) :: l
            integer :: i
            allocate (l%items(occ%n), l%keys(occ%n), l%key_line(occ%n), l%key_col(occ%n))
            do i = 1, occ%n
                l%items(i) = occ%items(i)%value
                l%keys(i)%s = occ%items(i)%name
                l%key_line(i) = occ%items(i)%line
                l%key_col(i) = occ%items(i)%col
            end do
            ov = pack_values(VK_FACTOR, l)
        end function occurrence_value

        integer function factor_max(fname)
            character(len=*), intent(in) :: fname
            integer :: i
            factor_max = 1
            associate (def => ctx%user_macros%cmds(icmd))
                do i = 1, def%nkw
                    if (def%kws(i)%parent == 0 .and. def%kws(i)%name == fname) &
                        factor_max = def%kws(i)%max
                end do
            end associate
        end function factor_max
    end procedure call_user_macro

end submodule deck_interp_macros
