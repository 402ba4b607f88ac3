!> The run context: everything one parasol run knows, passed explicitly to every handler
!> (no global mutable state). It holds the deck (path, text lines, syntax tree), the
!> catalog, the registry of command handlers, the symbol table and the concepts it owns,
!> the unit bindings (--unit N=PATH), the output directory and listings (.mess, .resu),
!> and the TEST_RESU counters.
!>
!> A session (doc/aster-tests.md) runs several command files in order; they share one
!> syntax tree and one namespace (scope 0). A file after the first starts with that
!> namespace put aside (`stash`) and POURSUITE() brings it back, as Code_Aster's
!> POURSUITE restores the previous file's database. Imported modules (from NAME import ...)
!> each get a namespace of their own (scope = their source index), as Python modules do.
module run_context
    use, intrinsic :: iso_fortran_env, only: error_unit
    use kinds, only: i4, i8
    use strings, only: string_t, to_text, ends_with
    use run_deadline, only: deadline_t
    use progress, only: progress_t
    use status, only: status_t, set_error, STATUS_IO_ERROR, STATUS_INTERNAL
    use atomic_file, only: atomic_file_t
    use deck_ast, only: ast_t
    use deck_value, only: value_t, append_string, VK_CONCEPT
    use deck_heap, only: heap_t
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use deck_catalog, only: catalog_t
    use deck_catalog_data, only: build_catalog
    implicit none
    private

    !> A registered handler. at_check: side-effect free and cheap (function commands): it
    !> also runs in the check pass, so its own errors are found by `parasol --check`.
    !> reuse: the handler handles reuse=CONCEPT (cmd%reuse; doc/architecture.md, "reuse");
    !> without it a deck's reuse= is refused as not built yet.
    type, public :: handler_entry_t
        character(len=:), allocatable :: name
        procedure(command_handler), pointer, nopass :: run => null()
        logical :: at_check = .false.
        logical :: reuse = .false.
    end type handler_entry_t

    !> A concept owned by the context; boxes never move, so pointers to obj stay valid.
    type, public :: concept_box_t
        class(concept_t), allocatable :: obj
    end type concept_box_t

    type :: box_ref_t
        type(concept_box_t), pointer :: box => null()
    end type box_ref_t

    !> A deck variable. scope: 0 for the command files' namespace, else the source index
    !> of the module whose namespace holds it.
    type, public :: symbol_t
        character(len=:), allocatable :: name
        type(value_t) :: value
        integer :: line = 0
        integer :: scope = 0
    end type symbol_t

    !> One source file of the session: a command file (module = '') or an imported module.
    !>  name : as used in messages (the path as given or as joined to its folder)
    !>  dir : its folder with a trailing '/' ('' = current folder)
    !>  file : its index in ast%files;  root : its N_MODULE node
    !>  state (modules): 0 not run in this pass, 1 being imported, 2 imported
    type, public :: source_t
        character(len=:), allocatable :: name, dir, module
        type(string_t), allocatable :: lines(:)
        integer :: file = 0, root = 0, state = 0
    end type source_t

    !> Sources and namespaces lookups (see scope_of_file).
    integer, parameter, public :: SCOPE_SESSION = 0

    !> One use of a concept's method, attribute or operator in the deck (doc/architecture.md,
    !> "Concept methods"): `TAB.EXTR_TABLE()` (name 'EXTR_TABLE', called), `tab.DY` (name
    !> 'DY', not called), `TAB['DX', 1]` (name '__getitem__', args = the index), `a - b`
    !> ('__sub__' on a, args = [b]; '__rsub__' on b when a is no concept), `a == b`
    !> ('__eq__'), `len(c)` ('__len__'). Python's special names, so that a handler reads as
    !> the Code_Aster Python API it mirrors.
    !>  args : positional arguments (lists and dicts as flat values, deck_value)
    !>  kwargs : keyword arguments, a VK_FACTOR value (nitems(kwargs) = 0 when none)
    type, public :: method_call_t
        character(len=:), allocatable :: name
        logical :: called = .false.
        type(value_t), allocatable :: args(:)
        type(value_t) :: kwargs
    end type method_call_t

    !> A registered method handler: methods of concepts of type `type_name` ('*' = any
    !> type) named `name` ('*' = any attribute read without a handler of its own, e.g. the
    !> columns of a table).
    type, public :: method_entry_t
        character(len=:), allocatable :: type_name, name
        procedure(method_handler), pointer, nopass :: run => null()
    end type method_entry_t

    type, public :: run_context_t
        character(len=:), allocatable :: deck_path   !< as given on the command line
        character(len=:), allocatable :: deck_name   !< file name used in messages
        character(len=:), allocatable :: deck_dir    !< folder of the deck ('' = cwd)
        character(len=:), allocatable :: deck_stem   !< file name without .comm
        character(len=:), allocatable :: outdir      !< where listings go ('' = cwd)
        type(string_t), allocatable :: lines(:)      !< deck source lines (for the echo)
        type(ast_t) :: ast                           !< the parsed deck
        type(catalog_t) :: catalog
        type(catalog_t) :: user_macros              !< the deck's own (deck_interp_macros)
        type(handler_entry_t), allocatable :: handlers(:)
        integer :: nhandler = 0
        type(method_entry_t), allocatable :: methods(:)   !< concept methods (register_method)
        integer :: nmethod = 0
        !> The check pass stopped early (at check_stop_file:check_stop_line): the flow of the
        !> deck depends there on a value known only when the deck runs (a table's cell ...).
        logical :: check_stopped = .false.
        character(len=:), allocatable :: check_stop_file
        integer :: check_stop_line = 0
        !> why it stopped there when not for a value known only when the deck runs
        character(len=:), allocatable :: check_stop_reason
        type(symbol_t), allocatable :: symbols(:)
        integer :: nsymbol = 0
        type(box_ref_t), allocatable, private :: boxes(:)
        integer :: nbox = 0
        integer(i4), allocatable :: unit_numbers(:)
        type(string_t), allocatable :: unit_paths(:)
        type(atomic_file_t) :: mess, resu
        logical :: checking = .false.   !< true during the check pass (nothing runs)
        logical :: finished = .false.   !< FIN has run
        integer :: n_ok = 0, n_nook = 0 !< TEST_RESU check lines
        integer :: statement = 0        !< AST node of the statement being evaluated
        integer :: echoed = 0           !< last statement echoed to the .mess
        integer :: ncommand = 0         !< commands run so far
        ! ---- the session: command files, modules, namespaces ----
        type(source_t), allocatable :: sources(:)  !< command files first, then modules
        integer :: nsource = 0
        integer :: ncommand_file = 0               !< sources(1:ncommand_file) run in order
        integer :: file_index = 0                  !< the command file being evaluated
        integer, allocatable :: file_scope(:)      !< ast file index -> scope
        type(symbol_t), allocatable :: stash(:)    !< the earlier files' names (POURSUITE)
        integer :: nstash = 0
        logical :: stashed = .false.               !< a stash waits for POURSUITE
        logical :: continued = .false.             !< POURSUITE ran in this file
        type(string_t), allocatable :: module_names(:), module_paths(:)  !< F nom lines
        integer :: import_depth = 0                !< modules being imported (nested)
        ! ---- loops (doc/deck-language.md, "Loops") ----
        integer :: loop_control = 0                !< 1 break, 2 continue pending
        type(value_t), allocatable :: loops(:)     !< the sequence each running loop walks
        integer :: nloop = 0
        !> The lists and dicts of the deck (deck_heap): shared, as Python's.
        type(heap_t) :: heap
        !> print() output not yet ended by a line end (print(..., end=''))
        character(len=:), allocatable :: print_line
        !> The result of a command whose Code_Aster result is a plain value (catalog type
        !> 'entier': DEFI_FICHIER's free unit): set by its handler (has_plain_result)
        type(value_t) :: plain_result
        logical :: has_plain_result = .false.
        !> The names the running command made with ctx%produce (its CO('NAME') outputs)
        type(string_t), allocatable :: produced(:)
        !> > 0 while a def, a comprehension or an import runs: their values live on the
        !> evaluator's stack, so the heap is not collected then
        integer :: gc_hold = 0
        integer(i8) :: iterations = 0              !< loop iterations in this pass
        integer(i8) :: built = 0                   !< sequence items built in this pass
        type(deadline_t) :: deadline               !< P time_limit of an export file
        !> Where long work reports its progress (cli's reporter; null: nobody listens).
        !> A pointer, so that handlers can hand it down to the analyses.
        class(progress_t), pointer :: progress => null()
        !> Result files (MED) written so far in this run: a later IMPR_RESU adds to them, as
        !> Code_Aster adds to the file of a unit, instead of replacing them.
        type(string_t), allocatable :: result_files(:)
    contains
        procedure :: register => ctx_register
        procedure :: find_handler => ctx_find_handler
        procedure :: register_method => ctx_register_method
        procedure :: find_method => ctx_find_method
        procedure :: method_names => ctx_method_names
        procedure :: concept_value => ctx_concept_value
        procedure :: produce => ctx_produce
        procedure :: bind_unit => ctx_bind_unit
        procedure :: release_unit => ctx_release_unit
        procedure :: unit_of_path => ctx_unit_of_path
        procedure :: unit_path => ctx_unit_path
        procedure :: output_path => ctx_output_path
        procedure :: in_outdir => ctx_in_outdir
        procedure :: write_mess => ctx_write_mess
        procedure :: write_warning => ctx_write_warning
        procedure :: write_resu => ctx_write_resu
        procedure :: check_listings => ctx_check_listings
        procedure :: count_test => ctx_count_test
        procedure :: set_symbol => ctx_set_symbol
        procedure :: find_symbol => ctx_find_symbol
        procedure :: delete_symbol => ctx_delete_symbol
        procedure :: own_concept => ctx_own_concept
        procedure :: reset_symbols => ctx_reset_symbols
        procedure :: add_source => ctx_add_source
        procedure :: scope_of_file => ctx_scope_of_file
        procedure :: source_of_file => ctx_source_of_file
        procedure :: bind_module => ctx_bind_module
        procedure :: begin_file => ctx_begin_file
        procedure :: continue_session => ctx_continue_session
        procedure :: stashed_name => ctx_stashed_name
    end type run_context_t

    !> A command handler: runs one validated command.
    !>  ctx : inout, the run context;  cmd : in, the validated command (defaults filled)
    !>  result : out, the concept produced (leave unallocated for commands without result)
    !>  st : out, a located error (use cmd%error_at(KEY, message, st[, code]))
    abstract interface
        subroutine command_handler(ctx, cmd, result, st)
            import :: run_context_t, command_t, concept_t, status_t
            type(run_context_t), intent(inout) :: ctx
            type(command_t), intent(in) :: cmd
            class(concept_t), allocatable, intent(out) :: result
            type(status_t), intent(out) :: st
        end subroutine command_handler
    end interface

    !> A concept method handler (register_method; doc/architecture.md, "Concept methods").
    !>  ctx : inout, the run context (own a new concept with ctx%concept_value)
    !>  obj : in, the concept whose method is used (its data may be changed: reuse semantics)
    !>  call : in, the method name, whether it is called, its arguments
    !>  result : out, the value the expression takes (VK_NONE when the method returns None)
    !>  st : out, an error message; the interpreter locates it at the use in the deck
    abstract interface
        subroutine method_handler(ctx, obj, call, result, st)
            import :: run_context_t, concept_t, method_call_t, value_t, status_t
            type(run_context_t), intent(inout) :: ctx
            class(concept_t), pointer, intent(in) :: obj
            type(method_call_t), intent(in) :: call
            type(value_t), intent(out) :: result
            type(status_t), intent(out) :: st
        end subroutine method_handler
    end interface

    public :: command_handler, method_handler, init_context

contains

    !> Prepares a context for `deck_path` (catalog built, nothing registered yet).
    !>  ctx : out;  deck_path : in, the deck file;  outdir : in, '' = current directory
    subroutine init_context(ctx, deck_path, outdir)
        type(run_context_t), intent(out) :: ctx
        character(len=*), intent(in) :: deck_path, outdir
        integer :: slash, dot
        ctx%deck_path = deck_path
        slash = index(deck_path, '/', back=.true.)
        ctx%deck_dir = deck_path(1:slash)
        ctx%deck_name = deck_path
        ctx%deck_stem = deck_path(slash + 1:)
        dot = index(ctx%deck_stem, '.', back=.true.)
        if (dot > 1) ctx%deck_stem = ctx%deck_stem(1:dot - 1)
        ctx%outdir = outdir
        call build_catalog(ctx%catalog)
        allocate (ctx%handlers(16), ctx%symbols(64), ctx%boxes(64), ctx%methods(16))
        allocate (ctx%unit_numbers(0), ctx%unit_paths(0), ctx%lines(0))
        allocate (ctx%sources(4), ctx%file_scope(0), ctx%stash(0))
        allocate (ctx%module_names(0), ctx%module_paths(0))
        allocate (ctx%loops(8))
        call ctx%heap%reset()
        ctx%print_line = ''
    end subroutine init_context

    !> Registers the handler of command `name` (replacing an earlier one).
    !>  at_check : optional, also run it in the check pass (side-effect-free commands)
    !>  reuse : optional, the handler handles reuse=CONCEPT of a reentrant command
    subroutine ctx_register(self, name, handler, at_check, reuse)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        procedure(command_handler) :: handler
        logical, intent(in), optional :: at_check, reuse
        type(handler_entry_t), allocatable :: bigger(:)
        integer :: k
        k = self%find_handler(name)
        if (k == 0) then
            if (self%nhandler == size(self%handlers)) then
                allocate (bigger(2 * size(self%handlers)))
                bigger(1:self%nhandler) = self%handlers(1:self%nhandler)
                call move_alloc(bigger, self%handlers)
            end if
            self%nhandler = self%nhandler + 1
            k = self%nhandler
        end if
        self%handlers(k)%name = name
        self%handlers(k)%run => handler
        self%handlers(k)%at_check = .false.
        if (present(at_check)) self%handlers(k)%at_check = at_check
        self%handlers(k)%reuse = .false.
        if (present(reuse)) self%handlers(k)%reuse = reuse
    end subroutine ctx_register

    !> Index of the handler of `name`, 0 if none.
    integer function ctx_find_handler(self, name)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: name
        integer :: k
        ctx_find_handler = 0
        do k = 1, self%nhandler
            if (self%handlers(k)%name == name) then
                ctx_find_handler = k
                return
            end if
        end do
    end function ctx_find_handler

    !> Registers the handler of method (or attribute, or Python special name) `name` of
    !> the concepts of catalog type `type_name` (replacing an earlier one). '*' as
    !> type_name: every type; '*' as name: every attribute read (obj.NAME, not called, not
    !> a special name) without a handler of its own, e.g. the columns of a table.
    subroutine ctx_register_method(self, type_name, name, handler)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: type_name, name
        procedure(method_handler) :: handler
        type(method_entry_t), allocatable :: bigger(:)
        integer :: k, found
        found = 0
        do k = 1, self%nmethod
            if (self%methods(k)%type_name == type_name .and. self%methods(k)%name == name) &
                found = k
        end do
        if (found == 0) then
            if (self%nmethod == size(self%methods)) then
                allocate (bigger(2 * size(self%methods)))
                bigger(1:self%nmethod) = self%methods(1:self%nmethod)
                call move_alloc(bigger, self%methods)
            end if
            self%nmethod = self%nmethod + 1
            found = self%nmethod
        end if
        self%methods(found)%type_name = type_name
        self%methods(found)%name = name
        self%methods(found)%run => handler
    end subroutine ctx_register_method

    !> Index of the handler of method `name` of a concept of type `type_name`, 0 if none:
    !> the exact pair first, then (type, '*'), ('*', name), ('*', '*'). A '*' name stands
    !> for attribute reads only (obj.NAME, not called): a call needs its own handler.
    !>  called : optional, the use is a call obj.name(...) (default .false.)
    integer function ctx_find_method(self, type_name, name, called) result(found)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: type_name, name
        logical, intent(in), optional :: called
        integer :: k, pass
        character(len=:), allocatable :: t, n
        logical :: is_call
        is_call = .false.
        if (present(called)) is_call = called
        found = 0
        do pass = 1, 4
            t = type_name; n = name
            if (pass == 2 .or. pass == 4) then
                if (is_call .or. name(1:min(2, len(name))) == '__') cycle
                n = '*'
            end if
            if (pass >= 3) t = '*'
            do k = 1, self%nmethod
                if (self%methods(k)%type_name == t .and. self%methods(k)%name == n) then
                    found = k
                    return
                end if
            end do
        end do
    end function ctx_find_method

    !> The method names registered for concepts of type `type_name` (for messages).
    function ctx_method_names(self, type_name) result(names)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: type_name
        type(string_t), allocatable :: names(:)
        integer :: k
        allocate (names(0))
        do k = 1, self%nmethod
            if (self%methods(k)%name == '*') cycle
            if (self%methods(k)%type_name == type_name .or. self%methods(k)%type_name == '*') &
                call append_string(names, self%methods(k)%name)
        end do
    end function ctx_method_names

    !> Takes ownership of a concept a method made (`TAB.EXTR_TABLE()`) and gives the deck
    !> value that refers to it.
    !>  obj : inout, the new concept (moved);  v : out, VK_CONCEPT;  st : out
    subroutine ctx_concept_value(self, obj, v, st)
        class(run_context_t), intent(inout) :: self
        class(concept_t), allocatable, intent(inout) :: obj
        type(value_t), intent(out) :: v
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: ptr
        if (allocated(obj)) then
            if (.not. allocated(obj%name)) obj%name = ''
        end if
        call self%own_concept(obj, ptr, st)
        if (st%failed()) return
        v%kind = VK_CONCEPT
        v%obj => ptr
        v%s = ptr%type_name()
    end subroutine ctx_concept_value

    !> Makes concept `obj` the deck name `name`: what a command does for a keyword given
    !> CO('NAME') (Code_Aster's outputs besides the result: ASSEMBLAGE's matrices,
    !> MACRO_ELAS_MULT's ...). The context owns it; the name is bound in the command files'
    !> namespace, as Code_Aster binds it in the deck's.
    !>  name : the text of the CO;  obj : inout, the concept (moved);  st : out
    subroutine ctx_produce(self, name, obj, st)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        class(concept_t), allocatable, intent(inout) :: obj
        type(status_t), intent(out) :: st
        type(value_t) :: v
        if (allocated(obj)) obj%name = name
        call self%concept_value(obj, v, st)
        if (st%failed()) return
        call self%set_symbol(name, v, 0, SCOPE_SESSION)
        if (.not. allocated(self%produced)) allocate (self%produced(0))
        call append_string(self%produced, name)
    end subroutine ctx_produce

    !> Binds logical unit `unit` to `path` (--unit N=PATH).
    subroutine ctx_bind_unit(self, unit, path)
        class(run_context_t), intent(inout) :: self
        integer, intent(in) :: unit
        character(len=*), intent(in) :: path
        self%unit_numbers = [self%unit_numbers, int(unit, i4)]
        call append_string(self%unit_paths, path)
    end subroutine ctx_bind_unit

    !> Frees logical unit `unit` (DEFI_FICHIER ACTION='LIBERER'): its bindings are gone.
    !>  found : out, the unit was bound
    subroutine ctx_release_unit(self, unit, found)
        class(run_context_t), intent(inout) :: self
        integer, intent(in) :: unit
        logical, intent(out) :: found
        integer(i4), allocatable :: numbers(:)
        type(string_t), allocatable :: paths(:)
        integer :: k
        found = .false.
        allocate (numbers(0), paths(0))
        do k = 1, size(self%unit_numbers)
            if (self%unit_numbers(k) == unit) then
                found = .true.
                cycle
            end if
            numbers = [numbers, self%unit_numbers(k)]
            call append_string(paths, self%unit_paths(k)%s)
        end do
        call move_alloc(numbers, self%unit_numbers)
        call move_alloc(paths, self%unit_paths)
    end subroutine ctx_release_unit

    !> The logical unit bound to file `path` (the latest binding), 0 if none.
    integer function ctx_unit_of_path(self, path) result(unit)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: path
        integer :: k
        unit = 0
        do k = size(self%unit_paths), 1, -1
            if (self%unit_paths(k)%s == path) then
                unit = self%unit_numbers(k)
                return
            end if
        end do
    end function ctx_unit_of_path

    !> The file of logical unit `unit` for a reader of format `format` (ASTER, GMSH, MED).
    !> An unbound unit 20 is the deck's stem with the format's extension beside the deck
    !> (ssnl130a.comm -> ssnl130a.mail), as design.md says.
    !>  path : out;  st : out, STATUS_IO_ERROR when the unit is unbound
    subroutine ctx_unit_path(self, unit, format, path, st)
        class(run_context_t), intent(in) :: self
        integer, intent(in) :: unit
        character(len=*), intent(in) :: format
        character(len=:), allocatable, intent(out) :: path
        type(status_t), intent(out) :: st
        integer :: k
        do k = size(self%unit_numbers), 1, -1
            if (self%unit_numbers(k) == unit) then
                path = self%unit_paths(k)%s
                return
            end if
        end do
        path = ''
        if (unit == 20) then
            select case (format)
            case ('ASTER')
                path = self%deck_dir // self%deck_stem // '.mail'
            case ('GMSH')
                path = self%deck_dir // self%deck_stem // '.msh'
            case ('MED')
                path = self%deck_dir // self%deck_stem // '.med'
            end select
            if (len(path) > 0) return
        end if
        call set_error(st, STATUS_IO_ERROR, 'logical unit ' // to_text(int(unit, i4)) // &
                       ' is not bound to a file (use --unit ' // to_text(int(unit, i4)) // &
                       '=PATH)')
    end subroutine ctx_unit_path

    !> outdir/<stem><suffix>, e.g. ctx%output_path('.vtk').
    function ctx_output_path(self, suffix) result(path)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: suffix
        character(len=:), allocatable :: path
        path = self%in_outdir(self%deck_stem // suffix)
    end function ctx_output_path

    !> `file` in the output folder (as given when there is none).
    function ctx_in_outdir(self, file) result(path)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: file
        character(len=:), allocatable :: path
        path = file
        if (len(self%outdir) > 0) then
            if (ends_with(self%outdir, '/')) then
                path = self%outdir // file
            else
                path = self%outdir // '/' // file
            end if
        end if
    end function ctx_in_outdir

    !> Writes one line to the .mess (nothing during the check pass or without a file).
    !> Each line is flushed: the .mess grows as the run goes (its temporary name, see
    !> atomic_file; the final name appears when the run ends).
    subroutine ctx_write_mess(self, line)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: line
        if (self%checking) return
        call self%mess%write_line(line)
        call self%mess%flush()
    end subroutine ctx_write_mess

    !> A located warning ("mesh.mail:12: warning: ..."): a line of the .mess, and of stderr
    !> so that it is seen beside the error it may explain (nothing during the check pass).
    subroutine ctx_write_warning(self, line)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: line
        if (self%checking) return
        call self%mess%write_line(line)
        write (error_unit, '(a)') line
    end subroutine ctx_write_warning

    !> Writes one line to the .resu (nothing during the check pass or without a file).
    subroutine ctx_write_resu(self, line)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: line
        if (self%checking) return
        call self%resu%write_line(line)
    end subroutine ctx_write_resu

    !> Hands both listings' lines to the system, then STATUS_IO_ERROR (unlocated) when a
    !> write to the .mess or the .resu has failed, e.g. on a full disk: that listing cannot
    !> be published whole, so the run cannot end well and the dispatcher, which calls this
    !> before each command, stops it there (`before` names that command and where it is)
    !> instead of computing on.
    subroutine ctx_check_listings(self, before, st)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: before
        type(status_t), intent(inout) :: st
        call self%mess%flush()
        call self%resu%flush()
        if (self%mess%failed()) then
            call set_error(st, STATUS_IO_ERROR, self%mess%error_message() // &
                ' (the run stopped before ' // before // ')')
        else if (self%resu%failed()) then
            call set_error(st, STATUS_IO_ERROR, self%resu%error_message() // &
                ' (the run stopped before ' // before // ')')
        end if
    end subroutine ctx_check_listings

    !> Counts one TEST_RESU check line (ok = .true. for OK, .false. for NOOK).
    subroutine ctx_count_test(self, ok)
        class(run_context_t), intent(inout) :: self
        logical, intent(in) :: ok
        if (ok) then
            self%n_ok = self%n_ok + 1
        else
            self%n_nook = self%n_nook + 1
        end if
    end subroutine ctx_count_test

    !> Binds deck variable `name` (assignment) in namespace `scope` (default: the command
    !> files' namespace, SCOPE_SESSION).
    subroutine ctx_set_symbol(self, name, value, line, scope)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: value
        integer, intent(in) :: line
        integer, intent(in), optional :: scope
        type(symbol_t), allocatable :: bigger(:)
        integer :: k, sc
        sc = SCOPE_SESSION
        if (present(scope)) sc = scope
        k = self%find_symbol(name, sc)
        if (k == 0) then
            if (self%nsymbol == size(self%symbols)) then
                allocate (bigger(2 * size(self%symbols)))
                bigger(1:self%nsymbol) = self%symbols(1:self%nsymbol)
                call move_alloc(bigger, self%symbols)
            end if
            self%nsymbol = self%nsymbol + 1
            k = self%nsymbol
        end if
        self%symbols(k)%name = name
        self%symbols(k)%value = value
        self%symbols(k)%line = line
        self%symbols(k)%scope = sc
    end subroutine ctx_set_symbol

    !> Index of deck variable `name` in namespace `scope` (default SCOPE_SESSION), 0 if
    !> unbound.
    integer function ctx_find_symbol(self, name, scope)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: name
        integer, intent(in), optional :: scope
        integer :: k, sc
        sc = SCOPE_SESSION
        if (present(scope)) sc = scope
        ctx_find_symbol = 0
        do k = self%nsymbol, 1, -1
            if (self%symbols(k)%scope /= sc) cycle
            if (self%symbols(k)%name == name) then
                ctx_find_symbol = k
                return
            end if
        end do
    end function ctx_find_symbol

    !> Removes deck variable `name` of namespace `scope` (Python's del NAME); false when it
    !> is not bound.
    logical function ctx_delete_symbol(self, name, scope) result(found)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        integer, intent(in) :: scope
        integer :: k, j
        k = self%find_symbol(name, scope)
        found = k > 0
        if (.not. found) return
        do j = k, self%nsymbol - 1
            self%symbols(j) = self%symbols(j + 1)
        end do
        self%nsymbol = self%nsymbol - 1
    end function ctx_delete_symbol

    !> Takes ownership of a concept (moved, not copied) and returns a stable pointer to it.
    subroutine ctx_own_concept(self, obj, ptr, st)
        class(run_context_t), intent(inout) :: self
        class(concept_t), allocatable, intent(inout) :: obj
        class(concept_t), pointer, intent(out) :: ptr
        type(status_t), intent(out) :: st
        type(box_ref_t), allocatable :: bigger(:)
        ptr => null()
        if (.not. allocated(obj)) then
            call set_error(st, STATUS_INTERNAL, 'no concept to store')
            return
        end if
        if (self%nbox == size(self%boxes)) then
            allocate (bigger(2 * size(self%boxes)))
            bigger(1:self%nbox) = self%boxes(1:self%nbox)
            call move_alloc(bigger, self%boxes)
        end if
        self%nbox = self%nbox + 1
        allocate (self%boxes(self%nbox)%box)
        call move_alloc(obj, self%boxes(self%nbox)%box%obj)
        ptr => self%boxes(self%nbox)%box%obj
    end subroutine ctx_own_concept

    !> Forgets every variable and frees every concept (between the check and run passes,
    !> and at the end of a run).
    subroutine ctx_reset_symbols(self)
        class(run_context_t), intent(inout) :: self
        integer :: k
        self%nsymbol = 0
        do k = 1, self%nbox
            if (associated(self%boxes(k)%box)) deallocate (self%boxes(k)%box)
        end do
        self%nbox = 0
        self%finished = .false.
        self%check_stopped = .false.
        if (allocated(self%check_stop_reason)) deallocate (self%check_stop_reason)
        self%nstash = 0
        self%stashed = .false.
        self%continued = .false.
        self%file_index = 0
        self%import_depth = 0
        self%loop_control = 0
        self%nloop = 0
        self%iterations = 0
        self%built = 0
        self%gc_hold = 0
        call self%heap%reset()
        self%print_line = ''
        do k = 1, self%nsource
            self%sources(k)%state = 0
        end do
    end subroutine ctx_reset_symbols

    !> Registers a parsed source file; returns its index. A module's namespace is its
    !> index (scope_of_file); command files share SCOPE_SESSION.
    !>  name, dir : as in source_t;  module : '' for a command file, else the module name
    !>  lines : its text lines;  file : its index in ast%files;  root : its N_MODULE node
    function ctx_add_source(self, name, dir, module, lines, file, root) result(k)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name, dir, module
        type(string_t), intent(in) :: lines(:)
        integer, intent(in) :: file, root
        integer :: k
        type(source_t), allocatable :: bigger(:)
        integer, allocatable :: scopes(:)
        if (self%nsource == size(self%sources)) then
            allocate (bigger(2 * size(self%sources)))
            do k = 1, self%nsource
                call move_alloc(self%sources(k)%name, bigger(k)%name)
                call move_alloc(self%sources(k)%dir, bigger(k)%dir)
                call move_alloc(self%sources(k)%module, bigger(k)%module)
                call move_alloc(self%sources(k)%lines, bigger(k)%lines)
                bigger(k)%file = self%sources(k)%file
                bigger(k)%root = self%sources(k)%root
                bigger(k)%state = self%sources(k)%state
            end do
            call move_alloc(bigger, self%sources)
        end if
        self%nsource = self%nsource + 1
        k = self%nsource
        self%sources(k)%name = name
        self%sources(k)%dir = dir
        self%sources(k)%module = module
        self%sources(k)%lines = lines
        self%sources(k)%file = file
        self%sources(k)%root = root
        self%sources(k)%state = 0
        if (file > size(self%file_scope)) then
            allocate (scopes(file))
            scopes = SCOPE_SESSION
            scopes(1:size(self%file_scope)) = self%file_scope
            call move_alloc(scopes, self%file_scope)
        end if
        if (len(module) > 0) self%file_scope(file) = k
    end function ctx_add_source

    !> The namespace of the code in ast file `file`: SCOPE_SESSION for command files and
    !> FORMULE strings, the module's source index for a module.
    pure integer function ctx_scope_of_file(self, file)
        class(run_context_t), intent(in) :: self
        integer, intent(in) :: file
        ctx_scope_of_file = SCOPE_SESSION
        if (file >= 1 .and. file <= size(self%file_scope)) &
            ctx_scope_of_file = self%file_scope(file)
    end function ctx_scope_of_file

    !> The source index of ast file `file`, 0 if it is no source (a FORMULE string).
    pure integer function ctx_source_of_file(self, file)
        class(run_context_t), intent(in) :: self
        integer, intent(in) :: file
        integer :: k
        ctx_source_of_file = 0
        do k = 1, self%nsource
            if (self%sources(k)%file == file) then
                ctx_source_of_file = k
                return
            end if
        end do
    end function ctx_source_of_file

    !> Binds module name `name` to the file `path` (an export file's `F nom` line), found
    !> by `from name import ...` before the file beside the deck.
    subroutine ctx_bind_module(self, name, path)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name, path
        call append_string(self%module_names, name)
        call append_string(self%module_paths, path)
    end subroutine ctx_bind_module

    !> Starts command file k of the session: it becomes the current file (name, lines,
    !> syntax tree root) and, after the first, the namespace of the earlier files is put
    !> aside until POURSUITE brings it back (continue_session) or DEBUT drops it.
    subroutine ctx_begin_file(self, k)
        class(run_context_t), intent(inout) :: self
        integer, intent(in) :: k
        integer :: j, n
        self%file_index = k
        self%deck_name = self%sources(k)%name
        self%lines = self%sources(k)%lines
        self%ast%root = self%sources(k)%root
        self%finished = .false.
        self%continued = .false.
        self%statement = 0
        if (k == 1) return
        ! Module namespaces stay; the session's names wait for POURSUITE.
        n = 0
        do j = 1, self%nsymbol
            if (self%symbols(j)%scope == SCOPE_SESSION) n = n + 1
        end do
        if (allocated(self%stash)) deallocate (self%stash)
        allocate (self%stash(n))
        n = 0
        do j = 1, self%nsymbol
            if (self%symbols(j)%scope == SCOPE_SESSION) then
                n = n + 1
                self%stash(n) = self%symbols(j)
            end if
        end do
        self%nstash = n
        self%stashed = .true.
        n = 0
        do j = 1, self%nsymbol
            if (self%symbols(j)%scope /= SCOPE_SESSION) then
                n = n + 1
                if (n /= j) self%symbols(n) = self%symbols(j)
            end if
        end do
        self%nsymbol = n
    end subroutine ctx_begin_file

    !> POURSUITE: the names of the earlier command files are defined again (a name this
    !> file assigned before POURSUITE keeps its new value). drop = .true. (DEBUT in a later
    !> file) forgets them instead: a new session.
    !>  restored : out, how many names came back
    subroutine ctx_continue_session(self, drop, restored)
        class(run_context_t), intent(inout) :: self
        logical, intent(in) :: drop
        integer, intent(out) :: restored
        integer :: j
        restored = 0
        if (.not. drop) then
            do j = 1, self%nstash
                if (self%find_symbol(self%stash(j)%name) > 0) cycle
                call self%set_symbol(self%stash(j)%name, self%stash(j)%value, &
                                     self%stash(j)%line)
                restored = restored + 1
            end do
            self%continued = .true.
        end if
        self%nstash = 0
        self%stashed = .false.
    end subroutine ctx_continue_session

    !> True when `name` is one of the earlier files' names waiting for POURSUITE.
    logical function ctx_stashed_name(self, name)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: name
        integer :: j
        ctx_stashed_name = .false.
        if (.not. self%stashed) return
        do j = 1, self%nstash
            if (self%stash(j)%name == name) then
                ctx_stashed_name = .true.
                return
            end if
        end do
    end function ctx_stashed_name

end module run_context
