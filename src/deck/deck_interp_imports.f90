!> The deck evaluator (deck_interpreter), its imports (doc/deck-language.md, "Modules"):
!> `import M [as N]`, `from M import A [as B], ...` and `from M import *`, anywhere (a def's
!> import binds its locals). M is a module of the deck (NAME.py, bound by an export file's
!> `F nom` line or beside the importing file; run once per pass in a namespace of its own),
!> math, Code_Aster's command modules (their commands are built in), or a module parasol
!> does not provide (numpy, scipy, code_aster's Python library, ...): its names are bound to
!> stand-ins, a located warning says so, and the deck stops, located, where it uses one.
submodule(deck_interpreter) deck_interp_imports
    use deck_math, only: builtin_id, PI_VALUE, E_VALUE
    use deck_suggest, only: did_you_mean
    implicit none

    !> Python modules decks import that parasol does not provide: bound to stand-ins.
    character(len=*), parameter :: FOREIGN_MODULES = ' numpy scipy sys os re copy time ' // &
        'string pickle json collections itertools functools random shutil glob subprocess ' // &
        'pathlib datetime medcoupling MEDLoader mpi4py matplotlib pandas '
    !> VK_MODULE value%i: math, and a module parasol does not provide (a deck module is its
    !> source index, > 0).
    integer(i8), parameter :: MODULE_MATH = -1, MODULE_FOREIGN = 0
    !> What code_aster.Cata.Syntax gives for user macros (deck_interp_macros).
    character(len=*), parameter :: CATA_SYNTAX = ' SIMP FACT MACRO EXCLUS UN_PARMI ' // &
        'AU_MOINS_UN PRESENT_PRESENT PRESENT_ABSENT ENSEMBLE '

contains

    module procedure exec_import
        character(len=:), allocatable :: module, bound_as
        integer :: k, src, name_node
        type(value_t) :: m
        if (ctx%ast%nodes(id)%kind == N_IMPORT) then
            do k = 1, ctx%ast%nkids(id)
                name_node = ctx%ast%kid(id, k)
                module = ctx%ast%nodes(name_node)%text
                bound_as = first_word(module)
                if (ctx%ast%nkids(name_node) > 0) &
                    bound_as = ctx%ast%nodes(ctx%ast%kid(name_node, 1))%text
                call module_value(module, name_node, m)
                if (st%failed()) return
                if (ctx%ast%nkids(name_node) == 0 .and. index(module, '.') > 0 .and. &
                    m%i > 0) then
                    call fail(st, ctx, name_node, 'import ' // module // ': a module of the ' &
                              // 'deck is NAME.py (no package)'); return
                end if
                if (ctx%ast%nkids(name_node) == 0 .and. index(module, '.') > 0) &
                    m = module_stand_in(first_word(module), m)
                call bind_name(ctx, name_node, bound_as, m, frame)
            end do
            return
        end if
        module = ctx%ast%nodes(id)%text
        if (module == 'math') then
            call from_math()
        else if (module == 'code_aster.Commands' .or. module == 'code_aster.Cata.Commands' &
                 .or. module == 'Accas' .or. module == 'Cata.cata') then
            call from_commands()
        else if (module == 'code_aster' .or. index(module, 'code_aster.') == 1 .or. &
                 foreign(module)) then
            call from_foreign()
        else if (index(module, '.') > 0) then
            call fail(st, ctx, id, 'module ' // module // ' is not available in parasol ' // &
                '(built in: math, code_aster.Commands; a module of the deck is NAME.py)')
        else
            call import_module(ctx, id, module, src, st)
            if (st%failed()) return
            call bind_imported(ctx, id, src, st, frame)
        end if
    contains
        !> The value `import M` binds for module M: math, a deck module (run now), or a
        !> stand-in for a module parasol does not provide (with a located warning).
        subroutine module_value(name, node, mv)
            character(len=*), intent(in) :: name
            integer, intent(in) :: node
            type(value_t), intent(out) :: mv
            integer :: source
            mv%kind = VK_MODULE
            mv%s = name
            select case (name)
            case ('math')
                mv%i = MODULE_MATH
                return
            end select
            if (name == 'code_aster' .or. index(name, 'code_aster.') == 1 .or. &
                foreign(name)) then
                mv%i = MODULE_FOREIGN
                call warn_foreign(name, node)
                return
            end if
            if (index(name, '.') > 0) then
                call fail(st, ctx, node, 'module ' // name // ' is not available in parasol ' &
                    // '(built in: math, code_aster.Commands; a module of the deck is NAME.py)')
                return
            end if
            call import_module(ctx, node, name, source, st)
            mv%i = source
        end subroutine module_value

        !> `import a.b` binds a: for a module not provided, a stand-in named a.
        function module_stand_in(name, mv) result(out)
            character(len=*), intent(in) :: name
            type(value_t), intent(in) :: mv
            type(value_t) :: out
            out = mv
            out%s = name
        end function module_stand_in

        subroutine from_math()
            integer :: j, n
            character(len=:), allocatable :: name, alias
            type(value_t) :: x
            do j = 1, ctx%ast%nkids(id)
                n = ctx%ast%kid(id, j)
                name = ctx%ast%nodes(n)%text
                if (name == '*') cycle                      ! the math names are built in
                alias = name
                if (ctx%ast%nkids(n) > 0) alias = ctx%ast%nodes(ctx%ast%kid(n, 1))%text
                select case (name)
                case ('pi')
                    x = real_value(PI_VALUE)
                case ('e')
                    x = real_value(E_VALUE)
                case default
                    if (builtin_id(name) == 0 .and. .not. is_builtin('math.' // name)) then
                        call fail(st, ctx, n, 'math.' // name // ' is not built into ' // &
                            'parasol (known: sqrt exp log log10 sin cos tan asin acos atan ' // &
                            'atan2 sinh cosh tanh floor ceil fabs hypot degrees radians ' // &
                            'isclose pi e)'); return
                    end if
                    x%kind = VK_BUILTIN
                    x%s = name
                end select
                if (alias /= name .or. name == 'e') call bind_name(ctx, n, alias, x, frame)
            end do
        end subroutine from_math

        !> from code_aster.Commands import ...: the commands are built in (one the catalog
        !> does not know is reported where it is called); `as` on a command is refused.
        subroutine from_commands()
            integer :: j, n
            do j = 1, ctx%ast%nkids(id)
                n = ctx%ast%kid(id, j)
                if (ctx%ast%nkids(n) > 0) then
                    call fail(st, ctx, ctx%ast%kid(n, 1), 'renaming a command with "as" is ' &
                              // 'not part of the deck language (use its name)'); return
                end if
            end do
        end subroutine from_commands

        !> from M import A [as B] of a module parasol does not provide: each name a stand-in
        !> (Code_Aster's commands and _F excepted: they are built in).
        subroutine from_foreign()
            integer :: j, n
            character(len=:), allocatable :: name, alias
            type(value_t) :: x
            call warn_foreign(module, id)
            do j = 1, ctx%ast%nkids(id)
                n = ctx%ast%kid(id, j)
                name = ctx%ast%nodes(n)%text
                if (name == '*') cycle
                if (name == '_F' .or. ctx%catalog%find_command(name) > 0) cycle
                alias = name
                if (ctx%ast%nkids(n) > 0) alias = ctx%ast%nodes(ctx%ast%kid(n, 1))%text
                x%kind = VK_MODULE
                x%s = module // '.' // name
                x%i = MODULE_FOREIGN
                if (name == 'TestCase' .and. (module == 'code_aster.CA' .or. &
                    module == 'code_aster.Utilities')) then
                    x%kind = VK_BUILTIN; x%s = 'TestCase'; x%i = 0   ! deck_interp_testcase
                end if
                if (provided_for_macros(module, name)) then          ! deck_interp_macros
                    x%kind = VK_BUILTIN; x%s = 'Cata.' // name; x%i = 0
                end if
                if (module == 'code_aster.MedUtils' .and. &
                    name == 'splitMeshAndFieldsFromMedFile') then    ! deck_interp_medutils
                    x%kind = VK_BUILTIN; x%s = 'MedUtils.' // name; x%i = 0
                end if
                call bind_name(ctx, n, alias, x, frame)
            end do
        end subroutine from_foreign

        subroutine warn_foreign(name, node)
            character(len=*), intent(in) :: name
            integer, intent(in) :: node
            character(len=:), allocatable :: what
            if (first_word(name) == 'code_aster') then
                if (everything_provided()) return
                what = 'of Code_Aster''s Python library (' // name // ') parasol provides ' // &
                    'the commands and CA.TestCase; the deck stops where it uses anything else'
            else
                what = 'parasol does not provide the Python module ' // first_word(name) // &
                    '; the deck stops where it uses it'
            end if
            call ctx%write_warning(node_file(ctx, node) // ':' // &
                to_text(int(ctx%ast%nodes(node)%line, i4)) // ':' // &
                to_text(int(ctx%ast%nodes(node)%col, i4)) // ': warning: ' // what)
        end subroutine warn_foreign

        !> from code_aster.CA import TestCase, from code_aster.Commands import *: nothing
        !> the deck takes is missing.
        logical function everything_provided()
            integer :: j, n
            character(len=:), allocatable :: what
            everything_provided = .false.
            if (ctx%ast%nodes(id)%kind == N_IMPORT) return
            do j = 1, ctx%ast%nkids(id)
                n = ctx%ast%kid(id, j)
                what = ctx%ast%nodes(n)%text
                if (what == '_F' .or. ctx%catalog%find_command(what) > 0) cycle
                if (what == 'TestCase' .and. (module == 'code_aster.CA' .or. &
                    module == 'code_aster.Utilities')) cycle
                if (provided_for_macros(module, what)) cycle
                if (module == 'code_aster.MedUtils' .and. &
                    what == 'splitMeshAndFieldsFromMedFile') cycle
                ! Code_Aster's data structure types: the types of user macros' keywords
                if (module == 'code_aster.Cata.DataStructure' .and. what /= '*') cycle
                return
            end do
            everything_provided = .true.
        end function everything_provided
    end procedure exec_import

    !> True for the names of Code_Aster's library that make user macros: SIMP, FACT, MACRO
    !> and the rules of code_aster.Cata.Syntax, UserMacro of code_aster.Supervis.
    pure logical function provided_for_macros(module, name)
        character(len=*), intent(in) :: module, name
        provided_for_macros = (module == 'code_aster.Cata.Syntax' .and. &
            index(CATA_SYNTAX, ' ' // name // ' ') > 0) .or. (name == 'UserMacro' .and. &
            (module == 'code_aster.Supervis.ExecuteCommand' .or. module == 'code_aster.Supervis'))
    end function provided_for_macros

    !> 'a' of 'a.b.c'.
    pure function first_word(dotted) result(word)
        character(len=*), intent(in) :: dotted
        character(len=:), allocatable :: word
        integer :: dot
        dot = index(dotted, '.')
        word = dotted
        if (dot > 0) word = dotted(1:dot - 1)
    end function first_word

    !> True for a Python module decks import that parasol does not provide.
    pure logical function foreign(module)
        character(len=*), intent(in) :: module
        foreign = index(FOREIGN_MODULES, ' ' // first_word(module) // ' ') > 0
    end function foreign

    !> Finds, loads (first time) and runs (once per pass) module `module`; src is its
    !> source index. A module being imported again further down is an import cycle.
    recursive subroutine import_module(ctx, id, module, src, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: module
        integer, intent(out) :: src
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: path, dir, text, chain
        integer :: k, slash, saved_statement, saved_root
        type(status_t) :: lst
        src = 0
        do k = 1, ctx%nsource
            if (ctx%sources(k)%module == module) src = k
        end do
        if (src == 0) then
            call find_module(ctx, id, module, path, st)
            if (st%failed()) return
            call read_source_text(path, 'the module file', text, lst)
            if (lst%failed()) then
                call fail(st, ctx, id, lst%message); return
            end if
            slash = index(path, '/', back=.true.)
            dir = path(1:slash)
            saved_root = ctx%ast%root
            call load_source(ctx, text, path, dir, module, src, lst)
            ctx%ast%root = saved_root
            if (lst%failed()) then
                st = lst; return
            end if
        end if
        select case (ctx%sources(src)%state)
        case (2)
            return                                 ! run already in this pass
        case (1)
            chain = ''
            do k = 1, ctx%nsource
                if (ctx%sources(k)%state == 1) chain = chain // ctx%sources(k)%name // ' -> '
            end do
            call fail(st, ctx, id, 'import cycle: ' // chain // ctx%sources(src)%name // &
                ' (a module cannot import, directly or not, a module that imports it)'); return
        end select
        if (ctx%import_depth >= MAX_IMPORT_DEPTH) then
            call fail(st, ctx, id, 'modules imported more than ' // &
                to_text(int(MAX_IMPORT_DEPTH, i4)) // ' deep'); return
        end if
        ctx%sources(src)%state = 1
        call ctx%write_mess('  -- import of module ' // module // ' from ' // &
                            ctx%sources(src)%name // ' (' // node_where(ctx, id) // ')')
        ctx%import_depth = ctx%import_depth + 1
        ctx%gc_hold = ctx%gc_hold + 1
        saved_statement = ctx%statement
        do k = 1, ctx%ast%nkids(ctx%sources(src)%root)
            call exec_statement(ctx, ctx%ast%kid(ctx%sources(src)%root, k), st)
            if (st%failed() .or. ctx%check_stopped) exit
        end do
        ctx%statement = saved_statement
        ctx%import_depth = ctx%import_depth - 1
        ctx%gc_hold = ctx%gc_hold - 1
        if (st%failed()) return
        ctx%sources(src)%state = 2
    end subroutine import_module

    !> The file of module `module`: an `F nom` binding, else NAME.py beside the file that
    !> imports it.
    subroutine find_module(ctx, id, module, path, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: module
        character(len=:), allocatable, intent(out) :: path
        type(status_t), intent(inout) :: st
        integer :: k, src
        logical :: exists
        do k = size(ctx%module_names), 1, -1
            if (ctx%module_names(k)%s == module) then
                path = ctx%module_paths(k)%s
                return
            end if
        end do
        src = ctx%source_of_file(int(ctx%ast%nodes(id)%file))
        path = module // '.py'
        if (src > 0) path = ctx%sources(src)%dir // module // '.py'
        inquire (file=path, exist=exists)
        if (exists) return
        call fail(st, ctx, id, 'module ' // module // ' not found: no file ' // path // &
            ' and no "F nom ' // module // '.py" line in the export file (a module of the ' // &
            'deck is NAME.py beside it)')
    end subroutine find_module

    !> Binds the names an import asks for (or every public name for *) from module src's
    !> namespace into the namespace (or the def's frame) of the importing statement.
    subroutine bind_imported(ctx, id, src, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id, src
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        integer :: k, j, name_node, n
        type(string_t), allocatable :: known(:)
        character(len=:), allocatable :: name, alias
        type(value_t) :: v
        if (ctx%ast%nodes(ctx%ast%kid(id, 1))%text == '*') then
            n = ctx%nsymbol                    ! bind_name may append: walk the old ones
            do j = 1, n
                if (ctx%symbols(j)%scope /= src) cycle
                name = ctx%symbols(j)%name     ! copies: bind_name may move the table
                if (name(1:1) == '_') cycle    ! Python: * skips the _names
                v = ctx%symbols(j)%value
                call bind_name(ctx, id, name, v, frame)
            end do
            return
        end if
        do k = 1, ctx%ast%nkids(id)
            name_node = ctx%ast%kid(id, k)
            name = ctx%ast%nodes(name_node)%text
            alias = name
            if (ctx%ast%nkids(name_node) > 0) alias = &
                ctx%ast%nodes(ctx%ast%kid(name_node, 1))%text
            j = ctx%find_symbol(name, src)
            if (j == 0) then
                allocate (known(0))
                do j = 1, ctx%nsymbol
                    if (ctx%symbols(j)%scope == src) call append_string(known, &
                        ctx%symbols(j)%name)
                end do
                call fail(st, ctx, name_node, 'cannot import ' // name // ' from ' // &
                    ctx%sources(src)%name // ' (it does not define it' // &
                    did_you_mean(name, known) // ')'); return
            end if
            v = ctx%symbols(j)%value
            call bind_name(ctx, name_node, alias, v, frame)
        end do
    end subroutine bind_imported

end submodule deck_interp_imports
