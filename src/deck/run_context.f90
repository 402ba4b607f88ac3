!> The run context: everything one parasol run knows, passed explicitly to every handler
!> (no global mutable state). It holds the deck (path, text lines, syntax tree), the
!> catalog, the registry of command handlers, the symbol table and the concepts it owns,
!> the unit bindings (--unit N=PATH), the output directory and listings (.mess, .resu),
!> and the TEST_RESU counters.
module run_context
    use kinds, only: i4
    use strings, only: string_t, to_text, ends_with
    use status, only: status_t, set_error, STATUS_IO_ERROR, STATUS_INTERNAL
    use atomic_file, only: atomic_file_t
    use deck_ast, only: ast_t
    use deck_value, only: value_t, append_string
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use deck_catalog, only: catalog_t
    use deck_catalog_data, only: build_catalog
    implicit none
    private

    !> A registered handler. at_check: side-effect free and cheap (function commands): it
    !> also runs in the check pass, so its own errors are found by `parasol --check`.
    type, public :: handler_entry_t
        character(len=:), allocatable :: name
        procedure(command_handler), pointer, nopass :: run => null()
        logical :: at_check = .false.
    end type handler_entry_t

    !> A concept owned by the context; boxes never move, so pointers to obj stay valid.
    type, public :: concept_box_t
        class(concept_t), allocatable :: obj
    end type concept_box_t

    type :: box_ref_t
        type(concept_box_t), pointer :: box => null()
    end type box_ref_t

    !> A deck variable.
    type, public :: symbol_t
        character(len=:), allocatable :: name
        type(value_t) :: value
        integer :: line = 0
    end type symbol_t

    type, public :: run_context_t
        character(len=:), allocatable :: deck_path   !< as given on the command line
        character(len=:), allocatable :: deck_name   !< file name used in messages
        character(len=:), allocatable :: deck_dir    !< folder of the deck ('' = cwd)
        character(len=:), allocatable :: deck_stem   !< file name without .comm
        character(len=:), allocatable :: outdir      !< where listings go ('' = cwd)
        type(string_t), allocatable :: lines(:)      !< deck source lines (for the echo)
        type(ast_t) :: ast                           !< the parsed deck
        type(catalog_t) :: catalog
        type(handler_entry_t), allocatable :: handlers(:)
        integer :: nhandler = 0
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
        !> Result files (MED) written so far in this run: a later IMPR_RESU adds to them, as
        !> Code_Aster adds to the file of a unit, instead of replacing them.
        type(string_t), allocatable :: result_files(:)
    contains
        procedure :: register => ctx_register
        procedure :: find_handler => ctx_find_handler
        procedure :: bind_unit => ctx_bind_unit
        procedure :: unit_path => ctx_unit_path
        procedure :: output_path => ctx_output_path
        procedure :: write_mess => ctx_write_mess
        procedure :: write_resu => ctx_write_resu
        procedure :: count_test => ctx_count_test
        procedure :: set_symbol => ctx_set_symbol
        procedure :: find_symbol => ctx_find_symbol
        procedure :: own_concept => ctx_own_concept
        procedure :: reset_symbols => ctx_reset_symbols
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

    public :: command_handler, init_context

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
        allocate (ctx%handlers(16), ctx%symbols(64), ctx%boxes(64))
        allocate (ctx%unit_numbers(0), ctx%unit_paths(0), ctx%lines(0))
    end subroutine init_context

    !> Registers the handler of command `name` (replacing an earlier one).
    !>  at_check : optional, also run it in the check pass (side-effect-free commands)
    subroutine ctx_register(self, name, handler, at_check)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        procedure(command_handler) :: handler
        logical, intent(in), optional :: at_check
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

    !> Binds logical unit `unit` to `path` (--unit N=PATH).
    subroutine ctx_bind_unit(self, unit, path)
        class(run_context_t), intent(inout) :: self
        integer, intent(in) :: unit
        character(len=*), intent(in) :: path
        self%unit_numbers = [self%unit_numbers, int(unit, i4)]
        call append_string(self%unit_paths, path)
    end subroutine ctx_bind_unit

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
        path = self%deck_stem // suffix
        if (len(self%outdir) > 0) then
            if (ends_with(self%outdir, '/')) then
                path = self%outdir // path
            else
                path = self%outdir // '/' // path
            end if
        end if
    end function ctx_output_path

    !> Writes one line to the .mess (nothing during the check pass or without a file).
    subroutine ctx_write_mess(self, line)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: line
        if (self%checking) return
        call self%mess%write_line(line)
    end subroutine ctx_write_mess

    !> Writes one line to the .resu (nothing during the check pass or without a file).
    subroutine ctx_write_resu(self, line)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: line
        if (self%checking) return
        call self%resu%write_line(line)
    end subroutine ctx_write_resu

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

    !> Binds deck variable `name` (assignment).
    subroutine ctx_set_symbol(self, name, value, line)
        class(run_context_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: value
        integer, intent(in) :: line
        type(symbol_t), allocatable :: bigger(:)
        integer :: k
        k = self%find_symbol(name)
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
    end subroutine ctx_set_symbol

    !> Index of deck variable `name`, 0 if unbound.
    integer function ctx_find_symbol(self, name)
        class(run_context_t), intent(in) :: self
        character(len=*), intent(in) :: name
        integer :: k
        ctx_find_symbol = 0
        do k = self%nsymbol, 1, -1
            if (self%symbols(k)%name == name) then
                ctx_find_symbol = k
                return
            end if
        end do
    end function ctx_find_symbol

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
    end subroutine ctx_reset_symbols

end module run_context
