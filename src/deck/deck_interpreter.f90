!> The deck evaluator: runs the statements of a parsed deck over the Python subset of
!> doc/deck-language.md and dispatches each command call to its registered handler.
!>
!> A deck is evaluated twice (design.md): the check pass (ctx%checking) evaluates every
!> expression and validates every command against the catalog, producing placeholder
!> concepts (or running side-effect-free handlers registered with at_check); the run pass
!> then evaluates again and runs each command. Integer/real arithmetic follows Python 3 and
!> every operation is checked before it is done (no FP trap, located errors instead).
module deck_interpreter
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use system_error, only: readable_errno, errno_text
    use status, only: status_t, set_error, add_context, STATUS_DECK_ERROR, &
        STATUS_NOT_IMPLEMENTED, STATUS_INTERNAL, STATUS_IO_ERROR
    use deck_lexer, only: check_bytes
    use deck_ast
    use deck_parser, only: parse_deck
    use deck_value
    use deck_concept, only: concept_t, placeholder_concept_t, concept_display_name
    use deck_command, only: command_t
    use deck_validate, only: validate_command
    use deck_math
    use deck_suggest, only: did_you_mean
    use deck_sequence, only: sequence_item, sequence_slice, sequence_length, range_steps
    use run_context, only: run_context_t, method_call_t, SCOPE_SESSION
    implicit none
    private

    !> Deepest chain of def calls (recursion is not part of deck practice).
    integer, parameter :: MAX_CALL_DEPTH = 50
    !> Longest string, tuple or list built by *, + or append.
    integer, parameter :: MAX_REPEAT = 1000000
    !> Loop iterations in one pass over a session: far beyond deck practice (loops over
    !> groups, cells or instants), and a bound so that no deck hangs parasol.
    integer(i8), parameter :: MAX_LOOP_ITERATIONS = 1000000_i8
    !> Sequence items built or scanned in one pass: +, *, slices and append copy the
    !> sequence (values are flat copies), so a list of N items built by append costs about
    !> N**2 items; this bound (a few seconds of work) keeps a deck from hanging parasol.
    integer(i8), parameter :: MAX_BUILT_ITEMS = 20000000_i8
    !> Modules imported inside one another.
    integer, parameter :: MAX_IMPORT_DEPTH = 20
    !> ctx%loop_control after break / continue.
    integer, parameter :: LOOP_BREAK = 1, LOOP_CONTINUE = 2

    !> Local variables of one def call. `caller` is the frame of the calling def (null at
    !> top level): list.append updates every name bound to the same list (Python's shared
    !> lists) in these frames too.
    type, public :: frame_t
        type(string_t), allocatable :: names(:)
        type(value_t), allocatable :: values(:)
        integer :: n = 0
        integer :: depth = 0
        logical :: returned = .false.
        type(value_t) :: ret
        type(frame_t), pointer :: caller => null()
    end type frame_t

    public :: load_deck, deck_from_text, evaluate_deck, eval_expression, call_def_values
    public :: read_source_text, load_source, evaluate_session

contains

    !> Reads the deck file of ctx, checks its bytes, keeps its lines and parses it: the
    !> first command file of the session.
    !>  st : out, STATUS_IO_ERROR if unreadable; STATUS_DECK_ERROR located for bad content
    subroutine load_deck(ctx, st)
        type(run_context_t), intent(inout) :: ctx
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        call read_source_text(ctx%deck_path, 'the deck', text, st)
        if (st%failed()) return
        call deck_from_text(ctx, text, st)
    end subroutine load_deck

    !> Reads a whole text file.
    !>  path : in;  what : in, what it is for messages ('the deck', 'the module m')
    !>  text : out;  st : out, STATUS_IO_ERROR naming the file when it cannot be read
    subroutine read_source_text(path, what, text, st)
        character(len=*), intent(in) :: path, what
        character(len=:), allocatable, intent(out) :: text
        type(status_t), intent(out) :: st
        integer :: unit, ios, length, code
        text = ''
        ! the system's reason, once (the Fortran message would repeat the path)
        code = readable_errno(path)
        if (code /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot open ' // what // ' ' // path // &
                           ': ' // errno_text(code))
            return
        end if
        open (newunit=unit, file=path, access='stream', form='unformatted', &
              status='old', action='read', iostat=ios)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot open ' // what // ' ' // path)
            return
        end if
        inquire (unit=unit, size=length)
        deallocate (text)
        allocate (character(len=max(length, 0)) :: text)
        if (length > 0) read (unit, iostat=ios) text
        close (unit)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot read ' // what // ' ' // path)
        end if
    end subroutine read_source_text

    !> Parses deck text into ctx as its first command file (also used by tests without
    !> a file).
    subroutine deck_from_text(ctx, text, st)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: text
        type(status_t), intent(out) :: st
        integer :: k
        call load_source(ctx, text, ctx%deck_name, ctx%deck_dir, '', k, st)
        if (st%failed()) return
        ctx%ncommand_file = max(ctx%ncommand_file, 1)
        call ctx%begin_file(1)
    end subroutine deck_from_text

    !> Checks, splits and parses the text of one source file and registers it in ctx.
    !>  name : in, the file as named in messages;  dir : in, its folder ('' or ending '/')
    !>  module : in, '' for a command file, else the module name
    !>  k : out, its source index;  st : out, located errors (bytes, syntax, empty file)
    subroutine load_source(ctx, text, name, dir, module, k, st)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: text, name, dir, module
        integer, intent(out) :: k
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: lines(:)
        k = 0
        call check_bytes(text, name, st)
        if (st%failed()) return
        call split_lines(text, lines)
        call parse_deck(text, name, ctx%ast, st)
        if (st%failed()) return
        if (ctx%ast%nkids(ctx%ast%root) == 0 .and. len(module) == 0) then
            call set_error(st, STATUS_DECK_ERROR, 'empty deck: no statement to run (a deck ' &
                // 'starts with DEBUT() and ends with FIN())', file=name, line=1, column=1)
            return
        end if
        k = ctx%add_source(name, dir, module, lines, int(ctx%ast%nodes(ctx%ast%root)%file), &
                           int(ctx%ast%root))
    end subroutine load_source

    !> Evaluates the command files of the session in order (one pass). Each file after the
    !> first starts with the earlier files' names put aside: POURSUITE() brings them back.
    !> The .mess shows where each file starts.
    !>  st : out, the first error, located
    subroutine evaluate_session(ctx, st)
        type(run_context_t), intent(inout) :: ctx
        type(status_t), intent(out) :: st
        integer :: k
        do k = 1, ctx%ncommand_file
            call ctx%begin_file(k)
            if (ctx%ncommand_file > 1) then
                call ctx%write_mess('')
                call ctx%write_mess('# ==== command file ' // to_text(int(k, i4)) // ' of ' &
                    // to_text(int(ctx%ncommand_file, i4)) // ': ' // ctx%deck_name)
            end if
            call evaluate_deck(ctx, st)
            if (st%failed() .or. ctx%check_stopped) return
            if (k < ctx%ncommand_file .and. .not. ctx%finished) call ctx%write_mess( &
                'warning: ' // ctx%deck_name // ' has no FIN(); the next file starts')
        end do
    end subroutine evaluate_session

    subroutine split_lines(text, lines)
        character(len=*), intent(in) :: text
        type(string_t), allocatable, intent(inout) :: lines(:)
        integer :: i, start, n, stop_at
        n = 0
        do i = 1, len(text)
            if (text(i:i) == achar(10)) n = n + 1
        end do
        if (allocated(lines)) deallocate (lines)
        allocate (lines(n + 1))
        start = 1; n = 0
        do i = 1, len(text) + 1
            if (i > len(text)) then
                if (start > len(text)) exit
            else if (text(i:i) /= achar(10)) then
                cycle
            end if
            n = n + 1
            stop_at = i - 1
            if (stop_at >= start) then
                if (text(stop_at:stop_at) == achar(13)) stop_at = stop_at - 1
            end if
            lines(n)%s = text(start:stop_at)
            start = i + 1
        end do
        lines = lines(1:n)
    end subroutine split_lines

    !> Evaluates every top-level statement of the parsed deck (one pass).
    !>  st : out, the first error, located
    subroutine evaluate_deck(ctx, st)
        type(run_context_t), intent(inout) :: ctx
        type(status_t), intent(out) :: st
        integer :: k, stmt
        do k = 1, ctx%ast%nkids(ctx%ast%root)
            stmt = ctx%ast%kid(ctx%ast%root, k)
            if (ctx%finished) then
                call set_error(st, STATUS_DECK_ERROR, 'statement after FIN (FIN ends the ' // &
                    'deck; move it before FIN)', file=ctx%deck_name, &
                    line=ctx%ast%nodes(stmt)%line, column=ctx%ast%nodes(stmt)%col)
                return
            end if
            ctx%statement = stmt
            call exec_statement(ctx, stmt, st)
            if (st%failed() .or. ctx%check_stopped) return
        end do
    end subroutine evaluate_deck

    !> Ends the check pass at statement or expression `id`: the flow of the deck depends
    !> there on a value known only when it runs (a condition or a loop on a table's cell).
    !> The rest is validated as it runs (every command is validated before it runs).
    subroutine stop_check(ctx, id)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        if (.not. ctx%checking .or. ctx%check_stopped) return
        ctx%check_stopped = .true.
        ctx%check_stop_file = node_file(ctx, id)
        ctx%check_stop_line = ctx%ast%nodes(id)%line
    end subroutine stop_check

    ! ---- statements -------------------------------------------------------------------------

    recursive subroutine exec_statement(ctx, id, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        type(value_t) :: v
        integer :: k
        type(node_t) :: node
        if (ctx%check_stopped) return
        node = ctx%ast%nodes(id)       ! a copy: evaluation may grow the AST (FORMULE VALE)
        block
            select case (node%kind)
            case (N_ASSIGN)
                call eval(ctx, node%kids(1), v, st, frame, target=node%text)
                if (st%failed()) return
                call assign(ctx, id, node%text, v, frame)
            case (N_EXPR)
                if (is_append(ctx, node%kids(1))) then
                    call exec_append(ctx, node%kids(1), st, frame)
                else
                    call eval(ctx, node%kids(1), v, st, frame)
                end if
            case (N_DEF)
                v%kind = VK_DEF; v%s = node%text; v%i = id
                v%line = node%line; v%col = node%col
                call assign(ctx, id, node%text, v, frame)
            case (N_FOR)
                call exec_for(ctx, id, st, frame)
            case (N_BREAK)
                ctx%loop_control = LOOP_BREAK
            case (N_CONTINUE)
                ctx%loop_control = LOOP_CONTINUE
            case (N_IMPORT, N_FROM_IMPORT)
                call exec_import(ctx, id, st)
            case (N_IF)
                call eval(ctx, node%kids(1), v, st, frame)
                if (st%failed()) return
                if (v%kind == VK_UNKNOWN) then
                    call stop_check(ctx, id); return
                end if
                if (truth(v)) then
                    call exec_block(ctx, node%kids(2), st, frame)
                else if (size(node%kids) > 2) then
                    call exec_block(ctx, node%kids(3), st, frame)
                end if
            case (N_BLOCK)
                call exec_block(ctx, id, st, frame)
            case (N_RETURN)
                if (.not. present(frame)) then
                    call fail(st, ctx, id, '"return" outside a def'); return
                end if
                call eval(ctx, node%kids(1), v, st, frame)
                if (st%failed()) return
                frame%ret = v
                frame%returned = .true.
            case (N_PASS)
            case default
                k = node%kind
                call fail(st, ctx, id, 'unexpected statement (kind ' // to_text(int(k, i4)) &
                          // ')')
            end select
        end block
    end subroutine exec_statement

    recursive subroutine exec_block(ctx, block, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: block
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        integer :: k
        do k = 1, ctx%ast%nkids(block)
            call exec_statement(ctx, ctx%ast%kid(block, k), st, frame)
            if (st%failed() .or. ctx%check_stopped) return
            if (ctx%loop_control /= 0) return         ! break/continue: the loop decides
            if (present(frame)) then
                if (frame%returned) return
            end if
        end do
    end subroutine exec_block

    !> Binds `name` to v: a local of the def being run, else a name of the namespace of
    !> statement `id`'s file (the session's, or a module's).
    subroutine assign(ctx, id, name, v, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: v
        type(frame_t), intent(inout), optional :: frame
        integer :: k
        if (present(frame)) then
            do k = 1, frame%n
                if (frame%names(k)%s == name) then
                    frame%values(k) = v
                    return
                end if
            end do
            call append_string(frame%names, name)
            call append_value(frame%values, v)
            frame%n = frame%n + 1
        else
            call ctx%set_symbol(name, v, int(ctx%ast%nodes(id)%line), scope_of(ctx, id))
        end if
    end subroutine assign

    !> The namespace of the code of node `id` (SCOPE_SESSION or a module's).
    pure integer function scope_of(ctx, id)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        scope_of = ctx%scope_of_file(int(ctx%ast%nodes(id)%file))
    end function scope_of

    ! ---- loops ------------------------------------------------------------------------------

    !> for NAME in SEQUENCE: body. SEQUENCE is range(...) (counted, never built), a tuple or
    !> a list (a list appended to in the body is walked to its new end, as in Python).
    !> Every iteration counts against MAX_LOOP_ITERATIONS and polls the time limit.
    recursive subroutine exec_for(ctx, id, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        integer :: seq, body, slot, cursor
        integer(i8) :: first, step, count, k
        type(value_t) :: v, item_value
        character(len=:), allocatable :: name
        name = ctx%ast%nodes(id)%text
        seq = ctx%ast%kid(id, 1)
        body = ctx%ast%kid(id, 2)
        if (is_range_call(ctx, seq, frame)) then
            call range_bounds(ctx, seq, first, step, count, st, frame)
            if (st%failed()) return
            do k = 1, count
                call next_iteration(ctx, id, st)
                if (st%failed()) return
                call assign(ctx, id, name, int_value(first + (k - 1) * step), frame)
                if (loop_body_done(ctx, body, st, frame)) exit
            end do
            return
        end if
        call eval(ctx, seq, v, st, frame)
        if (st%failed()) return
        if (v%kind == VK_UNKNOWN) then
            call stop_check(ctx, id); return
        end if
        if (v%kind /= VK_TUPLE .and. v%kind /= VK_LIST) then
            call fail(st, ctx, seq, 'a for loop walks a tuple, a list or range(...), got ' // &
                      kind_label(v)); return
        end if
        call push_loop(ctx, v, slot)
        ! A cursor on the flat tree of the sequence (deck_value): append only adds atoms at
        ! the end, so the cursor stays valid when the list grows and the loop walks on.
        cursor = 1
        do
            if (.not. allocated(ctx%loops(slot)%tree)) exit
            if (cursor > size(ctx%loops(slot)%tree)) exit
            call next_iteration(ctx, id, st)
            if (st%failed()) exit
            item_value = tree_item(ctx%loops(slot), cursor)
            cursor = cursor + 1 + ctx%loops(slot)%tree(cursor)%nsub
            call assign(ctx, id, name, item_value, frame)
            if (loop_body_done(ctx, body, st, frame)) exit
        end do
        ctx%nloop = ctx%nloop - 1
    end subroutine exec_for

    !> The item whose atom is tree(j) of composite v.
    function tree_item(v, j) result(x)
        type(value_t), intent(in) :: v
        integer, intent(in) :: j
        type(value_t) :: x
        type(value_t) :: one
        one%kind = VK_TUPLE
        one%tree = v%tree(j:j + v%tree(j)%nsub)
        x = item(one, 1)
    end function tree_item

    !> Runs the body once; true when the loop must stop (break, return, error).
    recursive logical function loop_body_done(ctx, body, st, frame) result(done)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: body
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        call exec_block(ctx, body, st, frame)
        done = st%failed() .or. ctx%loop_control == LOOP_BREAK .or. ctx%check_stopped
        ctx%loop_control = 0
        if (present(frame)) done = done .or. frame%returned
    end function loop_body_done

    !> Counts one iteration against MAX_LOOP_ITERATIONS and polls the time limit.
    subroutine next_iteration(ctx, id, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        ctx%iterations = ctx%iterations + 1
        if (ctx%iterations > MAX_LOOP_ITERATIONS) then
            call fail(st, ctx, id, 'more than ' // to_text(MAX_LOOP_ITERATIONS) // &
                ' loop iterations in all (the limit MAX_LOOP_ITERATIONS keeps a deck from ' // &
                'hanging parasol; is a loop endless?)'); return
        end if
        call ctx%deadline%check('the for loop at ' // node_where(ctx, id), st)
        call add_context(st, file=node_file(ctx, id), line=int(ctx%ast%nodes(id)%line), &
                         column=int(ctx%ast%nodes(id)%col))
    end subroutine next_iteration

    !> True when node `seq` is a call of the built-in range (not a deck name `range`).
    logical function is_range_call(ctx, seq, frame)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: seq
        type(frame_t), intent(in), optional :: frame
        integer :: callee
        is_range_call = .false.
        if (ctx%ast%nodes(seq)%kind /= N_CALL) return
        callee = ctx%ast%kid(seq, 1)
        if (ctx%ast%nodes(callee)%kind /= N_NAME) return
        if (ctx%ast%nodes(callee)%text /= 'range') return
        is_range_call = .not. shadowed(ctx, 'range', scope_of(ctx, seq), frame)
    end function is_range_call

    !> range(stop) | range(start, stop[, step]) with integers: first value, step, count.
    recursive subroutine range_bounds(ctx, seq, first, step, count, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: seq
        integer(i8), intent(out) :: first, step, count
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        type(value_t), allocatable :: args(:)
        type(value_t) :: kwargs
        integer(i8) :: b(3)
        integer :: k
        character(len=:), allocatable :: message
        first = 0; step = 1; count = 0
        call eval_arguments(ctx, seq, args, kwargs, st, frame)
        if (st%failed()) return
        if (nitems(kwargs) > 0 .or. size(args) < 1 .or. size(args) > 3) then
            call fail(st, ctx, seq, 'range() takes 1 to 3 integers: range(stop), ' // &
                      'range(start, stop) or range(start, stop, step)'); return
        end if
        do k = 1, size(args)
            if (args(k)%kind == VK_UNKNOWN) then
                call stop_check(ctx, seq); return
            end if
            if (args(k)%kind /= VK_INT) then
                call fail(st, ctx, seq, 'range() takes integers, got ' // &
                          kind_label(args(k)) // ' (use int(...))'); return
            end if
            b(k) = args(k)%i
        end do
        if (size(args) == 1) then
            b(2) = b(1); b(1) = 0
        end if
        if (size(args) == 3) step = b(3)
        first = b(1)
        call range_steps(b(1), b(2), step, count, message)
        if (len(message) > 0) call fail(st, ctx, seq, message)
    end subroutine range_bounds

    !> Pushes the sequence a for loop walks (lists only matter: append may grow them).
    subroutine push_loop(ctx, v, slot)
        type(run_context_t), intent(inout) :: ctx
        type(value_t), intent(in) :: v
        integer, intent(out) :: slot
        type(value_t), allocatable :: bigger(:)
        logical, allocatable :: grown(:)
        integer :: k
        if (ctx%nloop == size(ctx%loops)) then
            allocate (bigger(2 * ctx%nloop), grown(2 * ctx%nloop))
            do k = 1, ctx%nloop
                bigger(k) = ctx%loops(k)
                grown(k) = ctx%loop_grown(k)
            end do
            call move_alloc(bigger, ctx%loops)
            call move_alloc(grown, ctx%loop_grown)
        end if
        ctx%nloop = ctx%nloop + 1
        slot = ctx%nloop
        ctx%loops(slot) = v
        ctx%loop_grown(slot) = .false.
    end subroutine push_loop

    ! ---- list.append --------------------------------------------------------------------

    !> True when expression `e` is a call NAME.append(...).
    logical function is_append(ctx, e)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: e
        integer :: attr
        is_append = .false.
        if (ctx%ast%nodes(e)%kind /= N_CALL) return
        attr = ctx%ast%kid(e, 1)
        if (ctx%ast%nodes(attr)%kind /= N_ATTR) return
        is_append = ctx%ast%nodes(attr)%text == 'append' .and. &
            ctx%ast%nodes(ctx%ast%kid(attr, 1))%kind == N_NAME
    end function is_append

    !> NAME.append(VALUE) as a statement. Python lists are shared between the names bound
    !> to them; parasol's values are copies, so the list is identified (value_t%i of a list)
    !> and every name and loop bound to it is updated: the deck's names, the module names,
    !> the locals of the running defs, the lists for loops walk. A copy parasol cannot
    !> update (the list inside a tuple, a list or a _F) is a located error rather than a
    !> silent difference from Python.
    recursive subroutine exec_append(ctx, e, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: e
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        integer :: attr, target_node, k
        type(value_t) :: old, x, new
        type(value_t), allocatable :: args(:)
        type(value_t) :: kwargs
        type(frame_t), pointer :: f
        integer(i8) :: n
        character(len=:), allocatable :: name
        attr = ctx%ast%kid(e, 1)
        target_node = ctx%ast%kid(attr, 1)
        if (ctx%ast%nodes(target_node)%kind /= N_NAME) then
            call fail(st, ctx, attr, 'append works on a list held by a name ' // &
                      '(NAME.append(VALUE))'); return
        end if
        name = ctx%ast%nodes(target_node)%text
        call eval(ctx, target_node, old, st, frame)
        if (st%failed()) return
        if (old%kind == VK_CONCEPT .or. old%kind == VK_UNKNOWN) then
            call eval(ctx, e, x, st, frame)        ! a concept's own append method
            return
        end if
        if (old%kind /= VK_LIST) then
            call fail(st, ctx, attr, name // ' is ' // kind_label(old) // ', append needs ' // &
                      'a list (a tuple cannot grow: build a list [ ... ])'); return
        end if
        call eval_arguments(ctx, e, args, kwargs, st, frame)
        if (st%failed()) return
        if (size(args) /= 1 .or. nitems(kwargs) > 0) then
            call fail(st, ctx, attr, 'append takes one value: ' // name // '.append(VALUE)')
            return
        end if
        x = args(1)
        if (holds_list(x, old%i)) then
            call fail(st, ctx, attr, 'a list cannot be appended to itself'); return
        end if
        if (nitems(old) + 1 > MAX_REPEAT) then
            call fail(st, ctx, attr, 'list too long (more than ' // &
                      to_text(int(MAX_REPEAT, i4)) // ' items)'); return
        end if
        new = appended(old, x)
        ! The work: the copy, and the scan of every name for other copies of the list.
        n = size(new%tree)
        do k = 1, ctx%nsymbol
            if (allocated(ctx%symbols(k)%value%tree)) n = n + size(ctx%symbols(k)%value%tree)
        end do
        call count_built(ctx, attr, n, st)
        if (st%failed()) return
        ! Every copy of the list: frames (this def and its callers), namespaces, loops.
        if (present(frame)) then
            f => frame
            do while (associated(f))
                do k = 1, f%n
                    call update_copy(f%values(k), f%names(k)%s)
                    if (st%failed()) return
                end do
                f => f%caller
            end do
        end if
        do k = 1, ctx%nsymbol
            call update_copy(ctx%symbols(k)%value, ctx%symbols(k)%name)
            if (st%failed()) return
        end do
        do k = 1, ctx%nloop
            if (ctx%loops(k)%kind == VK_LIST .and. ctx%loops(k)%i == old%i) then
                ctx%loops(k) = new
                ctx%loop_grown(k) = .true.
            else if (holds_list(ctx%loops(k), old%i)) then
                call fail(st, ctx, attr, 'the list ' // name // ' is also inside the ' // &
                    'sequence a running for loop walks; parasol cannot update that copy ' // &
                    '(append to a list before putting it in a tuple or list)'); return
            end if
        end do
    contains
        subroutine update_copy(v, holder)
            type(value_t), intent(inout) :: v
            character(len=*), intent(in) :: holder
            integer :: line, col
            if (v%kind == VK_LIST .and. v%i == old%i) then
                line = v%line; col = v%col
                v = new
                v%line = line; v%col = col
            else if (holds_list(v, old%i)) then
                call fail(st, ctx, attr, 'the list ' // name // ' is also inside ' // holder &
                    // ' (' // kind_label(v) // '); Python would change that copy too, ' // &
                    'parasol cannot (append to a list before putting it in a tuple, a ' // &
                    'list or a _F)')
            end if
        end subroutine update_copy
    end subroutine exec_append

    !> The list `list` with x appended (same identity), built on the flat tree.
    function appended(list, x) result(v)
        type(value_t), intent(in) :: list, x
        type(value_t) :: v
        type(value_t) :: one
        integer :: n
        one = sequence_value(VK_LIST, [x])          ! x's atom and its descendants
        n = 0
        if (allocated(list%tree)) n = size(list%tree)
        v%kind = VK_LIST
        v%i = list%i
        allocate (v%tree(n + size(one%tree)))
        if (n > 0) v%tree(1:n) = list%tree
        v%tree(n + 1:) = one%tree
    end function appended

    !> True when v is, or holds at any depth, a value known only when the deck runs.
    pure logical function holds_unknown(v)
        type(value_t), intent(in) :: v
        holds_unknown = v%kind == VK_UNKNOWN
        if (holds_unknown .or. .not. allocated(v%tree)) return
        holds_unknown = any(v%tree%kind == VK_UNKNOWN)
    end function holds_unknown

    !> True when composite v holds, at any depth, the list of identity `id`.
    pure logical function holds_list(v, id)
        type(value_t), intent(in) :: v
        integer(i8), intent(in) :: id
        integer :: j
        holds_list = v%kind == VK_LIST .and. v%i == id
        if (holds_list .or. .not. allocated(v%tree)) return
        do j = 1, size(v%tree)
            if (v%tree(j)%kind == VK_LIST .and. v%tree(j)%i == id) then
                holds_list = .true.
                return
            end if
        end do
    end function holds_list

    !> A new list value (its own identity, for append).
    function new_list(ctx, items) result(v)
        type(run_context_t), intent(inout) :: ctx
        type(value_t), intent(in) :: items(:)
        type(value_t) :: v
        v = sequence_value(VK_LIST, items)
        ctx%next_list = ctx%next_list + 1
        v%i = ctx%next_list
    end function new_list

    !> Counts n items built against MAX_BUILT_ITEMS.
    subroutine count_built(ctx, id, n, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        integer(i8), intent(in) :: n
        type(status_t), intent(inout) :: st
        ctx%built = ctx%built + n
        if (ctx%built > MAX_BUILT_ITEMS) call fail(st, ctx, id, 'more than ' // &
            to_text(MAX_BUILT_ITEMS) // ' sequence items built in all (the limit ' // &
            'MAX_BUILT_ITEMS keeps a deck from hanging parasol; +, slices and append ' // &
            'copy the sequence)')
    end subroutine count_built

    ! ---- imports ----------------------------------------------------------------------------

    !> import M / from M import * | A, B. `math` and `code_aster.Commands` are built in
    !> (no-ops); any other module is NAME.py, bound by an export file's `F nom` line or
    !> beside the importing file, run once per pass in a namespace of its own; the names
    !> asked for are then bound in the importing file's namespace.
    recursive subroutine exec_import(ctx, id, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: module
        integer :: k, src, name_node
        if (ctx%ast%nodes(id)%kind == N_IMPORT) then
            do k = 1, ctx%ast%nkids(id)
                module = ctx%ast%nodes(ctx%ast%kid(id, k))%text
                select case (module)
                case ('math', 'code_aster', 'code_aster.Commands')
                case default
                    call fail(st, ctx, id, 'import ' // module // ': only "import math" is ' &
                        // 'supported; a module of the deck is read with from ' // module // &
                        ' import NAME (or *)'); return
                end select
            end do
            return
        end if
        module = ctx%ast%nodes(id)%text
        select case (module)
        case ('math')
            do k = 1, ctx%ast%nkids(id)
                name_node = ctx%ast%kid(id, k)
                call check_math_name(ctx, name_node, st)
                if (st%failed()) return
            end do
            return
        case ('code_aster.Commands')
            do k = 1, ctx%ast%nkids(id)
                name_node = ctx%ast%kid(id, k)
                if (ctx%ast%nodes(name_node)%text == '*') cycle
                if (ctx%catalog%find_command(ctx%ast%nodes(name_node)%text) > 0) cycle
                if (ctx%ast%nodes(name_node)%text == '_F') cycle
                call fail(st, ctx, name_node, 'code_aster.Commands has no command ' // &
                    ctx%ast%nodes(name_node)%text // ' known to parasol' // &
                    did_you_mean(ctx%ast%nodes(name_node)%text, command_names(ctx))); return
            end do
            return
        end select
        if (module == 'code_aster' .or. index(module, 'code_aster.') == 1 .or. &
            index(module, '.') > 0) then
            call fail(st, ctx, id, 'module ' // module // ' is not available in parasol ' // &
                '(built in: math, code_aster.Commands; a module of the deck is NAME.py)')
            return
        end if
        call import_module(ctx, id, module, src, st)
        if (st%failed()) return
        call bind_imported(ctx, id, src, st)
    end subroutine exec_import

    !> from math import NAME: NAME must be one of the built-in math names.
    subroutine check_math_name(ctx, name_node, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: name_node
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: name
        name = ctx%ast%nodes(name_node)%text
        if (name == '*' .or. name == 'pi' .or. name == 'e') return
        if (builtin_id(name) > 0) return
        call fail(st, ctx, name_node, 'math.' // name // ' is not built into parasol ' // &
            '(known: sqrt exp log log10 sin cos tan asin acos atan atan2 sinh cosh tanh ' // &
            'floor ceil pi e)')
    end subroutine check_math_name

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
        saved_statement = ctx%statement
        do k = 1, ctx%ast%nkids(ctx%sources(src)%root)
            call exec_statement(ctx, ctx%ast%kid(ctx%sources(src)%root, k), st)
            if (st%failed()) exit
        end do
        ctx%statement = saved_statement
        ctx%import_depth = ctx%import_depth - 1
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
    !> namespace into the namespace of the importing statement.
    subroutine bind_imported(ctx, id, src, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id, src
        type(status_t), intent(inout) :: st
        integer :: k, j, name_node, target_scope, n
        type(string_t), allocatable :: known(:)
        character(len=:), allocatable :: name
        type(value_t) :: v
        target_scope = scope_of(ctx, id)
        if (ctx%ast%nodes(ctx%ast%kid(id, 1))%text == '*') then
            n = ctx%nsymbol                    ! set_symbol may append: walk the old ones
            do j = 1, n
                if (ctx%symbols(j)%scope /= src) cycle
                name = ctx%symbols(j)%name     ! copies: set_symbol may move the table
                if (name(1:1) == '_') cycle    ! Python: * skips the _names
                v = ctx%symbols(j)%value
                call ctx%set_symbol(name, v, int(ctx%ast%nodes(id)%line), target_scope)
            end do
            return
        end if
        do k = 1, ctx%ast%nkids(id)
            name_node = ctx%ast%kid(id, k)
            name = ctx%ast%nodes(name_node)%text
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
            call ctx%set_symbol(name, v, int(ctx%ast%nodes(id)%line), target_scope)
        end do
    end subroutine bind_imported

    !> 'file:line' of node id, for messages.
    function node_where(ctx, id) result(text)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=:), allocatable :: text
        text = node_file(ctx, id) // ':' // to_text(int(ctx%ast%nodes(id)%line, i4))
    end function node_where

    !> The file of node id as named in messages (the current command file if unknown).
    function node_file(ctx, id) result(name)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=:), allocatable :: name
        name = ctx%ast%file_name(id)
        if (len(name) == 0) name = ctx%deck_name
    end function node_file

    ! ---- expressions ------------------------------------------------------------------------

    !> Evaluates expression node `id` of ctx%ast (public entry, e.g. for tests).
    subroutine eval_expression(ctx, id, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(out) :: st
        call eval(ctx, id, v, st)
    end subroutine eval_expression

    recursive subroutine eval(ctx, id, v, st, frame, target)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        character(len=*), intent(in), optional :: target
        type(value_t) :: a, b, kwargs
        type(value_t), allocatable :: args(:)
        type(value_list_t) :: list
        integer :: k, nk, ios
        select case (ctx%ast%nodes(id)%kind)
        case (N_INT)
            v%kind = VK_INT
            read (ctx%ast%nodes(id)%text, *, iostat=ios) v%i
            if (ios /= 0) call fail(st, ctx, id, 'integer literal too large (at most ' // &
                'about 9.2E+18; write it as a real)')
        case (N_REAL)
            v%kind = VK_REAL
            ios = 0
            if (literal_out_of_range(ctx%ast%nodes(id)%text)) ios = 1
            if (ios == 0) read (ctx%ast%nodes(id)%text, *, iostat=ios) v%r
            if (ios == 0) then
                if (abs(v%r) > huge(v%r)) ios = 1
            end if
            if (ios /= 0) call fail(st, ctx, id, 'real literal out of range (the largest ' // &
                                    'real is about 1.8E+308)')
        case (N_STR)
            v = str_value(ctx%ast%nodes(id)%text)
        case (N_NAME)
            call lookup(ctx, id, v, st, frame)
            ! A name's value is located where it is used, not where it was bound, so an
            ! error about it (e.g. a concept of the wrong type) points at the use.
            v%line = ctx%ast%nodes(id)%line; v%col = ctx%ast%nodes(id)%col
        case (N_TUPLE, N_LIST)
            nk = ctx%ast%nkids(id)
            allocate (list%items(nk))
            do k = 1, nk
                call eval(ctx, ctx%ast%kid(id, k), list%items(k), st, frame)
                if (st%failed()) return
            end do
            if (ctx%ast%nodes(id)%kind == N_TUPLE) then
                v = pack_values(VK_TUPLE, list)
            else
                v = new_list(ctx, list%items)
            end if
        case (N_INDEX, N_SLICE)
            call eval_subscript(ctx, id, v, st, frame)
        case (N_ATTR)
            call eval(ctx, ctx%ast%kid(id, 1), a, st, frame)
            if (st%failed()) return
            allocate (args(0))
            call use_attribute(ctx, id, a, ctx%ast%nodes(id)%text, .false., args, kwargs, v, st)
        case (N_UNARY)
            call eval(ctx, ctx%ast%kid(id, 1), a, st, frame)
            if (st%failed()) return
            call unary(ctx, id, a, v, st)
        case (N_BINOP)
            call eval(ctx, ctx%ast%kid(id, 1), a, st, frame)
            if (st%failed()) return
            call eval(ctx, ctx%ast%kid(id, 2), b, st, frame)
            if (st%failed()) return
            call binary(ctx, id, ctx%ast%nodes(id)%text, a, b, v, st)
        case (N_COMPARE)
            call compare_chain(ctx, id, v, st, frame)
        case (N_AND, N_OR)
            do k = 1, ctx%ast%nkids(id)
                call eval(ctx, ctx%ast%kid(id, k), v, st, frame)
                if (st%failed()) return
                if (v%kind == VK_UNKNOWN) exit
                if (truth(v) .eqv. (ctx%ast%nodes(id)%kind == N_OR)) exit
            end do
        case (N_IFEXP)
            call eval(ctx, ctx%ast%kid(id, 2), a, st, frame)
            if (st%failed()) return
            if (a%kind == VK_UNKNOWN) then
                v = a
            else if (truth(a)) then
                call eval(ctx, ctx%ast%kid(id, 1), v, st, frame)
            else
                call eval(ctx, ctx%ast%kid(id, 3), v, st, frame)
            end if
        case (N_CALL)
            call eval_call(ctx, id, v, st, frame, target)
        case default
            call fail(st, ctx, id, 'unexpected expression')
        end select
        if (v%line == 0) then
            v%line = ctx%ast%nodes(id)%line; v%col = ctx%ast%nodes(id)%col
        end if
    end subroutine eval

    !> seq[i] and seq[start:stop:step] on a tuple or list (deck_sequence); a slice of a
    !> list is a new list.
    recursive subroutine eval_subscript(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        type(value_t) :: seq, b
        type(value_t), allocatable :: items(:)
        character(len=:), allocatable :: message, parts
        logical :: given(3)
        integer(i8) :: bounds(3)
        integer :: k, j
        call eval(ctx, ctx%ast%kid(id, 1), seq, st, frame)
        if (st%failed()) return
        if (seq%kind == VK_CONCEPT .or. seq%kind == VK_UNKNOWN) then
            if (ctx%ast%nodes(id)%kind /= N_INDEX) then
                call fail(st, ctx, id, kind_label(seq) // ' cannot be sliced'); return
            end if
            call eval(ctx, ctx%ast%kid(id, 2), b, st, frame)
            if (st%failed()) return
            call use_attribute(ctx, id, seq, '__getitem__', .true., [b], empty_kwargs(), v, st)
            return
        end if
        given = .false.; bounds = 0
        if (ctx%ast%nodes(id)%kind == N_INDEX) then
            parts = '100'
        else
            parts = ctx%ast%nodes(id)%text
        end if
        j = 1
        do k = 1, 3
            if (parts(k:k) /= '1') cycle
            j = j + 1
            call eval(ctx, ctx%ast%kid(id, j), b, st, frame)
            if (st%failed()) return
            if (b%kind == VK_NONE .and. ctx%ast%nodes(id)%kind == N_SLICE) cycle
            if (b%kind == VK_UNKNOWN) then
                v = b; return
            end if
            if (b%kind /= VK_INT) then
                call fail(st, ctx, ctx%ast%kid(id, j), 'an index must be an integer, got ' // &
                          kind_label(b) // ' (use int(...))'); return
            end if
            given(k) = .true.; bounds(k) = b%i
        end do
        if (ctx%ast%nodes(id)%kind == N_INDEX) then
            call sequence_item(seq, bounds(1), v, message)
            if (len(message) > 0) call fail(st, ctx, id, message)
            return
        end if
        call sequence_slice(seq, given, bounds, items, message)
        if (len(message) > 0) then
            call fail(st, ctx, id, message); return
        end if
        call count_built(ctx, id, int(size(items), i8), st)
        if (st%failed()) return
        if (seq%kind == VK_LIST) then
            v = new_list(ctx, items)
        else
            v = sequence_value(VK_TUPLE, items)
        end if
    end subroutine eval_subscript

    !> Name lookup: locals of the def, names of the code's namespace (the session's or its
    !> module's), built-ins.
    subroutine lookup(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(in), optional :: frame
        character(len=:), allocatable :: name
        integer :: k
        name = ctx%ast%nodes(id)%text
        if (present(frame)) then
            do k = frame%n, 1, -1
                if (frame%names(k)%s == name) then
                    v = frame%values(k)
                    return
                end if
            end do
        end if
        k = ctx%find_symbol(name, scope_of(ctx, id))
        if (k > 0) then
            v = ctx%symbols(k)%value
            return
        end if
        select case (name)
        case ('len')
            v%kind = VK_BUILTIN; v%s = name; return
        case ('range')
            call fail(st, ctx, id, 'range() is only supported as the sequence of a for ' // &
                      'loop (for i in range(n):)'); return
        case ('pi', 'math.pi')
            v = real_value(PI_VALUE); return
        case ('math.e')
            v = real_value(E_VALUE); return
        case ('True')
            v = bool_value(.true.); return
        case ('False')
            v = bool_value(.false.); return
        case ('None')
            v%kind = VK_NONE; return
        end select
        if (builtin_id(name) > 0) then
            v%kind = VK_BUILTIN; v%s = name
            return
        end if
        if (ctx%catalog%find_command(name) > 0 .or. name == '_F') then
            call fail(st, ctx, id, name // ' is a command: call it with (KEYWORD=value, ...)')
            return
        end if
        call undefined_name(ctx, id, name, st)
    end subroutine lookup

    !> "name 'X' is not defined", or "used before it is assigned" when a later statement
    !> assigns it, with a suggestion.
    subroutine undefined_name(ctx, id, name, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        integer :: k, s, root, src
        type(string_t), allocatable :: known(:)
        if (len(name) > 5) then
            if (name(1:5) == 'math.') then
                call fail(st, ctx, id, name // ' is not a known math function (known: ' // &
                    'sqrt exp log log10 sin cos tan asin acos atan atan2 sinh cosh tanh ' // &
                    'floor ceil, and the constants pi e)')
                return
            end if
        end if
        if (ctx%stashed_name(name) .and. scope_of(ctx, id) == SCOPE_SESSION) then
            call fail(st, ctx, id, 'name ' // name // ' is not defined yet in this file: ' // &
                'it belongs to the session of the earlier command files (continue it with ' // &
                'POURSUITE() before this line)')
            return
        end if
        root = ctx%ast%root
        src = ctx%source_of_file(int(ctx%ast%nodes(id)%file))
        if (src > 0) root = ctx%sources(src)%root
        do k = 1, ctx%ast%nkids(root)
            s = ctx%ast%kid(root, k)
            if ((ctx%ast%nodes(s)%kind == N_ASSIGN .or. ctx%ast%nodes(s)%kind == N_DEF) .and. &
                ctx%ast%nodes(s)%text == name .and. s /= ctx%statement) then
                if (ctx%ast%nodes(s)%line >= ctx%ast%nodes(id)%line) then
                    call fail(st, ctx, id, 'name ' // name // ' is used before it is ' // &
                        'assigned (assigned at line ' // to_text(ctx%ast%nodes(s)%line) // &
                        '; move that statement first)')
                    return
                end if
            end if
        end do
        allocate (known(0))
        do k = 1, ctx%nsymbol
            if (ctx%symbols(k)%scope == scope_of(ctx, id)) &
                call append_string(known, ctx%symbols(k)%name)
        end do
        do k = 1, ctx%catalog%ncmd
            call append_string(known, ctx%catalog%cmds(k)%name)
        end do
        call fail(st, ctx, id, 'name ' // name // ' is not defined' // &
                  did_you_mean(name, known))
    end subroutine undefined_name

    ! ---- calls ------------------------------------------------------------------------------

    recursive subroutine eval_call(ctx, id, v, st, frame, target)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        character(len=*), intent(in), optional :: target
        integer :: callee, icmd
        type(value_t) :: f
        type(value_t), allocatable :: args(:)
        type(value_t) :: kwargs
        character(len=:), allocatable :: name
        callee = ctx%ast%kid(id, 1)
        if (ctx%ast%nodes(callee)%kind == N_NAME) then
            name = ctx%ast%nodes(callee)%text
            block
                icmd = ctx%catalog%find_command(name)
                if (.not. shadowed(ctx, name, scope_of(ctx, id), frame)) then
                    if (icmd > 0 .or. name == '_F') then
                        call eval_arguments(ctx, id, args, kwargs, st, frame)
                        if (st%failed()) return
                        if (size(args) > 0) then
                            call fail(st, ctx, id, name // ' takes keyword arguments only ' &
                                      // '(KEYWORD=value)')
                            return
                        end if
                        if (icmd > 0) then
                            call run_command(ctx, icmd, callee, kwargs, v, st, target)
                        else
                            v = kwargs
                            v%kind = VK_FACTOR
                        end if
                        return
                    end if
                    if (is_command_like(name) .and. builtin_id(name) == 0) then
                        call fail(st, ctx, callee, 'unknown command ' // name // &
                                  did_you_mean(name, command_names(ctx)))
                        return
                    end if
                end if
            end block
        end if
        if (ctx%ast%nodes(callee)%kind == N_ATTR) then
            call eval(ctx, ctx%ast%kid(callee, 1), f, st, frame)
            if (st%failed()) return
            call eval_arguments(ctx, id, args, kwargs, st, frame)
            if (st%failed()) return
            call use_attribute(ctx, callee, f, ctx%ast%nodes(callee)%text, .true., args, &
                               kwargs, v, st)
            return
        end if
        call eval(ctx, callee, f, st, frame)
        if (st%failed()) return
        call eval_arguments(ctx, id, args, kwargs, st, frame)
        if (st%failed()) return
        if (nitems(kwargs) > 0 .and. f%kind /= VK_NONE) then
            call fail(st, ctx, id, 'keyword arguments are only for commands and _F')
            return
        end if
        if (f%kind == VK_UNKNOWN .or. any(args%kind == VK_UNKNOWN)) then
            v%kind = VK_UNKNOWN; return
        end if
        select case (f%kind)
        case (VK_BUILTIN)
            if (f%s == 'len') then
                call call_len(ctx, id, args, v, st)
            else
                call call_builtin(ctx, id, f%s, args, v, st)
            end if
        case (VK_DEF)
            call call_def_values(ctx, int(f%i), args, v, st, id, frame)
        case (VK_CONCEPT)
            call call_concept(ctx, callee, f, args, v, st)
        case default
            call fail(st, ctx, callee, kind_label(f) // ' cannot be called')
        end select
    end subroutine eval_call

    !> True when `name` is a local of the def or a name of namespace `scope`.
    logical function shadowed(ctx, name, scope, frame)
        type(run_context_t), intent(in) :: ctx
        character(len=*), intent(in) :: name
        integer, intent(in) :: scope
        type(frame_t), intent(in), optional :: frame
        integer :: k
        shadowed = ctx%find_symbol(name, scope) > 0
        if (present(frame)) then
            do k = 1, frame%n
                if (frame%names(k)%s == name) shadowed = .true.
            end do
        end if
    end function shadowed

    !> len(x) of a tuple, a list or a string.
    recursive subroutine call_len(ctx, id, args, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        integer(i8) :: n
        character(len=:), allocatable :: message
        type(value_t), allocatable :: none(:)
        if (size(args) /= 1) then
            call fail(st, ctx, id, 'len() takes 1 argument, got ' // &
                      to_text(int(size(args), i4))); return
        end if
        if (args(1)%kind == VK_CONCEPT) then
            allocate (none(0))
            call use_attribute(ctx, id, args(1), '__len__', .true., none, empty_kwargs(), v, st)
            return
        end if
        call sequence_length(args(1), n, message)
        if (len(message) > 0) then
            call fail(st, ctx, id, message); return
        end if
        v = int_value(n)
    end subroutine call_len

    !> Upper-case names with an underscore or of 4+ letters look like command names.
    pure logical function is_command_like(name)
        character(len=*), intent(in) :: name
        integer :: i
        is_command_like = len(name) >= 4
        do i = 1, len(name)
            if (index('ABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789', name(i:i)) == 0) &
                is_command_like = .false.
        end do
    end function is_command_like

    function command_names(ctx) result(names)
        type(run_context_t), intent(in) :: ctx
        type(string_t), allocatable :: names(:)
        integer :: k
        allocate (names(ctx%catalog%ncmd))
        do k = 1, ctx%catalog%ncmd
            names(k)%s = ctx%catalog%cmds(k)%name
        end do
    end function command_names

    !> Positional arguments, and keyword arguments as a VK_FACTOR value (located at the
    !> callee name).
    recursive subroutine eval_arguments(ctx, id, args, kwargs, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), allocatable, intent(out) :: args(:)
        type(value_t), intent(out) :: kwargs
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        type(value_list_t) :: kw
        integer :: k, a, nkw, npos
        npos = 0; nkw = 0
        do k = 2, ctx%ast%nkids(id)
            if (ctx%ast%nodes(ctx%ast%kid(id, k))%kind == N_KWARG) then
                nkw = nkw + 1
            else
                npos = npos + 1
            end if
        end do
        allocate (args(npos), kw%items(nkw), kw%keys(nkw), kw%key_line(nkw), kw%key_col(nkw))
        npos = 0; nkw = 0
        do k = 2, ctx%ast%nkids(id)
            a = ctx%ast%kid(id, k)
            if (ctx%ast%nodes(a)%kind == N_KWARG) then
                nkw = nkw + 1
                kw%keys(nkw)%s = ctx%ast%nodes(a)%text
                kw%key_line(nkw) = ctx%ast%nodes(a)%line
                kw%key_col(nkw) = ctx%ast%nodes(a)%col
                call eval(ctx, ctx%ast%kid(a, 1), kw%items(nkw), st, frame)
            else
                npos = npos + 1
                call eval(ctx, a, args(npos), st, frame)
            end if
            if (st%failed()) return
        end do
        kwargs = pack_values(VK_FACTOR, kw)
        kwargs%line = ctx%ast%nodes(ctx%ast%kid(id, 1))%line
        kwargs%col = ctx%ast%nodes(ctx%ast%kid(id, 1))%col
    end subroutine eval_arguments

    !> Calls def function `def_node` with positional values `args`.
    !>  call_id : AST node of the call (for messages);  frame : the caller's frame (depth)
    recursive subroutine call_def_values(ctx, def_node, args, v, st, call_id, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: def_node, call_id
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(frame_t), target :: local
        integer :: np, k
        np = ctx%ast%nkids(def_node) - 1
        if (size(args) /= np) then
            call fail(st, ctx, call_id, ctx%ast%nodes(def_node)%text // '() takes ' // &
                to_text(int(np, i4)) // ' argument(s), got ' // to_text(int(size(args), i4)))
            return
        end if
        local%depth = 1
        if (present(frame)) then
            local%depth = frame%depth + 1
            local%caller => frame
        end if
        if (local%depth > MAX_CALL_DEPTH) then
            call fail(st, ctx, call_id, 'def calls nested deeper than ' // &
                      to_text(int(MAX_CALL_DEPTH, i4)) // ' (recursion is not supported)')
            return
        end if
        allocate (local%names(np), local%values(np))
        do k = 1, np
            local%names(k)%s = ctx%ast%nodes(ctx%ast%kid(def_node, k))%text
            local%values(k) = args(k)
        end do
        local%n = np
        call exec_block(ctx, ctx%ast%kid(def_node, np + 1), st, local)
        if (st%failed()) return
        v = local%ret
    end subroutine call_def_values

    !> F(x, ...) for a concept: functions evaluate (through concept_t%call_real), others
    !> refuse. In the check pass a placeholder cannot be evaluated: the result is 0.0.
    subroutine call_concept(ctx, id, f, args, v, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: f
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(status_t) :: cst
        real(dp) :: y
        integer :: k
        do k = 1, size(args)
            if (.not. is_number(args(k))) then
                call fail(st, ctx, id, 'a function takes numbers, got ' // kind_label(args(k)))
                return
            end if
        end do
        if (.not. associated(f%obj)) then
            call fail(st, ctx, id, 'this concept cannot be called'); return
        end if
        call f%obj%call_real(as_real(args), y, cst)
        if (cst%failed()) then
            call fail(st, ctx, id, cst%message); return
        end if
        v = real_value(y)
    end subroutine call_concept

    !> Built-in functions on numbers (Python semantics for ints where it matters).
    subroutine call_builtin(ctx, id, name, args, v, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: xs(:)
        type(value_list_t) :: list
        real(dp), allocatable :: x(:)
        real(dp) :: r
        integer :: b, code, k
        logical :: all_int
        b = builtin_id(name)
        xs = args
        if ((b == B_MIN .or. b == B_MAX) .and. size(args) == 1) then
            if (args(1)%kind == VK_TUPLE .or. args(1)%kind == VK_LIST) then
                list = unpack_value(args(1))
                xs = list%items
            end if
        end if
        if (builtin_arity_of(b) > 0 .and. size(xs) /= builtin_arity_of(b)) then
            call fail(st, ctx, id, name // '() takes ' // to_text(int(builtin_arity_of(b), &
                i4)) // ' argument(s), got ' // to_text(int(size(xs), i4)))
            return
        end if
        if (size(xs) == 0) then
            call fail(st, ctx, id, name // '() needs at least one argument'); return
        end if
        all_int = .true.
        do k = 1, size(xs)
            if (.not. is_number(xs(k))) then
                call fail(st, ctx, id, name // '() expects numbers, got ' // &
                          kind_label(xs(k))); return
            end if
            if (xs(k)%kind == VK_REAL) all_int = .false.
        end do
        x = as_real(xs)
        call checked_call(b, x, size(x), r, code)
        if (code /= MATH_OK) then
            call fail(st, ctx, id, math_message(code, name // '()')); return
        end if
        select case (b)
        case (B_ABS, B_MIN, B_MAX)
            if (all_int) then
                v = int_value(nint(r, i8))
            else
                v = real_value(r)
            end if
        case (B_INT, B_FLOOR, B_CEIL)
            if (abs(r) >= 9.2e18_dp) then
                call fail(st, ctx, id, name // '() result out of the integer range'); return
            end if
            v = int_value(int(r, i8))
        case default
            v = real_value(r)
        end select
    end subroutine call_builtin

    ! ---- commands ---------------------------------------------------------------------------

    !> Validates and runs (or, in the check pass, stands in for) catalog command icmd.
    recursive subroutine run_command(ctx, icmd, name_node, kwargs, v, st, target)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: icmd, name_node
        type(value_t), intent(in) :: kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        character(len=*), intent(in), optional :: target
        type(command_t) :: cmd
        class(concept_t), allocatable :: result
        class(concept_t), pointer :: ptr
        integer :: h, line, col
        logical :: run_it
        character(len=:), allocatable :: file
        line = ctx%ast%nodes(name_node)%line; col = ctx%ast%nodes(name_node)%col
        file = node_file(ctx, name_node)
        if (ctx%finished) then
            call fail(st, ctx, name_node, 'command ' // ctx%catalog%cmds(icmd)%name // &
                      ' after FIN (FIN ends the deck)'); return
        end if
        if (ctx%import_depth > 0) then
            call fail(st, ctx, name_node, 'command ' // ctx%catalog%cmds(icmd)%name // &
                ' while a module is imported (a module gives def functions and values; ' // &
                'call commands in the command file)'); return
        end if
        call ctx%deadline%check(ctx%catalog%cmds(icmd)%name // ' at ' // &
                                node_where(ctx, name_node), st)
        if (st%failed()) then
            call add_context(st, file=file, line=line, column=col); return
        end if
        call ctx%check_listings(ctx%catalog%cmds(icmd)%name // ' at ' // &
                                node_where(ctx, name_node), st)
        if (st%failed()) return
        if (ctx%checking .and. holds_unknown(kwargs)) then
            ! A keyword takes a value known only when the deck runs (a table's cell): the
            ! command is validated then; here it stands in with a placeholder.
            cmd%name = ctx%catalog%cmds(icmd)%name
            cmd%result_type = ctx%catalog%cmds(icmd)%result_type
        else
            call validate_command(ctx%catalog, icmd, kwargs, file, line, col, cmd, st)
            if (st%failed()) return
        end if
        cmd%source = statement_source(ctx)
        h = ctx%find_handler(cmd%name)
        if (h > 0 .and. associated(cmd%reuse)) then
            if (.not. ctx%handlers(h)%reuse) then
                call cmd%error_at('reuse', cmd%name // '(reuse=...), which modifies ' // &
                    concept_display_name(cmd%reuse) // ' in place, is not built yet in ' // &
                    'parasol (leave reuse out and give the result a new name)', st, &
                    STATUS_NOT_IMPLEMENTED)
                return
            end if
        end if
        run_it = h > 0
        if (ctx%checking .and. h > 0) run_it = ctx%handlers(h)%at_check .and. &
            .not. holds_unknown(kwargs)
        if (.not. ctx%checking) then
            call echo_statement(ctx, cmd%name, line)
            if (h == 0) then
                call set_error(st, STATUS_NOT_IMPLEMENTED, cmd%name // &
                    ' is not implemented yet', file=file, line=line, column=col)
                return
            end if
        end if
        if (run_it) then
            block
                type(status_t) :: hst
                call ctx%handlers(h)%run(ctx, cmd, result, hst)
                if (hst%failed()) then
                    call add_context(hst, file=file, line=line, column=col, &
                                     command=cmd%name)
                    st = hst
                    return
                end if
            end block
        else if (len(cmd%result_type) > 0 .and. .not. associated(cmd%reuse)) then
            allocate (placeholder_concept_t :: result)
            select type (result)
            type is (placeholder_concept_t)
                result%kind_name = cmd%result_type
            end select
        end if
        ctx%ncommand = ctx%ncommand + 1
        if (cmd%name == 'FIN') ctx%finished = .true.
        if (.not. allocated(result) .and. associated(cmd%reuse)) then
            ! reuse=X: the command modified X in place; the result is X itself (as in
            ! Code_Aster, where the command's result is the reused object)
            v%kind = VK_CONCEPT
            v%obj => cmd%reuse
            v%s = cmd%reuse%type_name()
            v%line = line; v%col = col
            call ctx%write_mess('    -> ' // cmd%reuse%summary() // ', modified in place (reuse)')
            return
        end if
        if (.not. allocated(result)) then
            if (len(cmd%result_type) > 0) call set_error(st, STATUS_INTERNAL, cmd%name // &
                ' produced no result', file=file, line=line, column=col)
            return
        end if
        result%name = ''
        if (present(target)) result%name = target
        call ctx%own_concept(result, ptr, st)
        if (st%failed()) return
        v%kind = VK_CONCEPT
        v%obj => ptr
        v%s = ptr%type_name()
        v%line = line; v%col = col
        call ctx%write_mess('    -> ' // ptr%summary())
    end subroutine run_command

    !> Writes the statement being evaluated to the .mess once, with its line numbers.
    subroutine echo_statement(ctx, name, line)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: name
        integer, intent(in) :: line
        integer :: l, first, last
        character(len=8) :: buf
        if (ctx%echoed == ctx%statement) then
            call ctx%write_mess('  -- ' // name // ' (line ' // to_text(int(line, i4)) // ')')
            return
        end if
        ctx%echoed = ctx%statement
        first = ctx%ast%nodes(ctx%statement)%line
        last = max(first, ctx%ast%nodes(ctx%statement)%end_line)
        call ctx%write_mess('')
        call ctx%write_mess('# ---- ' // name // ' (line ' // to_text(int(line, i4)) // ')')
        do l = first, min(last, size(ctx%lines))
            write (buf, '(i6)') l
            call ctx%write_mess(buf(1:6) // ' | ' // ctx%lines(l)%s)
        end do
    end subroutine echo_statement

    function statement_source(ctx) result(text)
        type(run_context_t), intent(in) :: ctx
        character(len=:), allocatable :: text
        integer :: l
        text = ''
        if (ctx%statement == 0) return
        do l = ctx%ast%nodes(ctx%statement)%line, &
               min(ctx%ast%nodes(ctx%statement)%end_line, size(ctx%lines))
            if (len(text) > 0) text = text // achar(10)
            text = text // ctx%lines(l)%s
        end do
    end function statement_source

    ! ---- concept methods (doc/architecture.md, "Concept methods") -----------------------------

    !> obj.name, obj.name(args...), obj[index], operators and len() on a concept: the
    !> handler registered for its type (ctx%register_method). In the check pass a
    !> placeholder concept stands for what a command will make: the value is known only
    !> when the deck runs (VK_UNKNOWN). Other values have no attributes in the deck
    !> language but those of lists (append).
    !>  id : the AST node the use is located at;  called : obj.name(...) rather than obj.name
    recursive subroutine use_attribute(ctx, id, obj, name, called, args, kwargs, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        logical, intent(in) :: called
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(method_call_t) :: call
        type(status_t) :: hst
        class(concept_t), pointer :: ptr
        integer :: k
        character(len=:), allocatable :: what
        if (obj%kind == VK_UNKNOWN) then
            v%kind = VK_UNKNOWN; return
        end if
        what = name
        if (called .and. name(1:min(2, len(name))) /= '__') what = name // '()'
        if (obj%kind == VK_LIST .and. name == 'append') then
            call fail(st, ctx, id, 'LIST.append(VALUE) is a statement of its own (it ' // &
                      'returns None)'); return
        end if
        if (obj%kind /= VK_CONCEPT .or. .not. associated(obj%obj)) then
            call fail(st, ctx, id, kind_label(obj) // ' has no attribute ' // name // &
                ' in the deck language'); return
        end if
        ptr => obj%obj
        select type (ptr)
        type is (placeholder_concept_t)
            v%kind = VK_UNKNOWN; return           ! check pass: made when the deck runs
        end select
        k = ctx%find_method(ptr%type_name(), name, called)
        if (k == 0) then
            call fail(st, ctx, id, 'a concept of type ' // ptr%type_name() // ' (' // &
                concept_display_name(ptr) // ') has no ' // method_word(name) // ' ' // what &
                // ' in parasol' // did_you_mean(name, ctx%method_names(ptr%type_name())) // &
                provided(ctx%method_names(ptr%type_name()))); return
        end if
        call%name = name
        call%called = called
        call%args = args
        call%kwargs = kwargs
        call ctx%methods(k)%run(ctx, ptr, call, v, hst)
        if (hst%failed()) then
            call fail(st, ctx, id, ptr%type_name() // ' ' // what // ': ' // hst%message)
            return
        end if
        if (v%line == 0) then
            v%line = ctx%ast%nodes(id)%line; v%col = ctx%ast%nodes(id)%col
        end if
    contains
        pure function method_word(n) result(word)
            character(len=*), intent(in) :: n
            character(len=:), allocatable :: word
            word = 'attribute'
            if (called) word = 'method'
            if (n(1:min(2, len(n))) == '__') word = 'operation'
        end function method_word
        function provided(names) result(text)
            type(string_t), intent(in) :: names(:)
            character(len=:), allocatable :: text
            integer :: j
            text = ' (it has none)'
            if (size(names) == 0) return
            text = ' (it has: '
            do j = 1, size(names)
                if (j > 1) text = text // ', '
                text = text // names(j)%s
            end do
            text = text // ')'
        end function provided
    end subroutine use_attribute

    !> True when value v is a concept (not a placeholder) with a handler for `name`.
    logical function has_method(ctx, v, name)
        type(run_context_t), intent(in) :: ctx
        type(value_t), intent(in) :: v
        character(len=*), intent(in) :: name
        has_method = .false.
        if (v%kind /= VK_CONCEPT .or. .not. associated(v%obj)) return
        has_method = ctx%find_method(v%obj%type_name(), name, .true.) > 0
    end function has_method

    !> Python's special name of a binary operator ('+' -> '__add__', reflected '__radd__').
    pure function operator_name(op, reflected) result(name)
        character(len=*), intent(in) :: op
        logical, intent(in) :: reflected
        character(len=:), allocatable :: name
        select case (op)
        case ('+')
            name = 'add'
        case ('-')
            name = 'sub'
        case ('*')
            name = 'mul'
        case ('/')
            name = 'truediv'
        case ('//')
            name = 'floordiv'
        case ('%')
            name = 'mod'
        case ('**')
            name = 'pow'
        case default
            name = 'op'
        end select
        if (reflected) name = 'r' // name
        name = '__' // name // '__'
    end function operator_name

    !> Python's special name of a comparison; reflected: the one the right operand answers
    !> (a < b is b > a).
    pure function compare_name(op, reflected) result(name)
        character(len=*), intent(in) :: op
        logical, intent(in) :: reflected
        character(len=:), allocatable :: name
        character(len=:), allocatable :: o
        o = op
        if (reflected) then
            select case (op)
            case ('<')
                o = '>'
            case ('<=')
                o = '>='
            case ('>')
                o = '<'
            case ('>=')
                o = '<='
            end select
        end if
        select case (o)
        case ('<')
            name = '__lt__'
        case ('<=')
            name = '__le__'
        case ('>')
            name = '__gt__'
        case ('>=')
            name = '__ge__'
        case ('==')
            name = '__eq__'
        case ('!=')
            name = '__ne__'
        case default
            name = '__cmp__'
        end select
    end function compare_name

    !> No keyword arguments (a VK_FACTOR without items).
    pure function empty_kwargs() result(v)
        type(value_t) :: v
        v%kind = VK_FACTOR
    end function empty_kwargs

    ! ---- operators --------------------------------------------------------------------------

    recursive subroutine unary(ctx, id, a, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: a
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: none(:)
        if (a%kind == VK_UNKNOWN) then
            v = a; return
        end if
        if (a%kind == VK_CONCEPT .and. ctx%ast%nodes(id)%text /= 'not') then
            allocate (none(0))
            call use_attribute(ctx, id, a, merge('__neg__', '__pos__', &
                ctx%ast%nodes(id)%text == '-'), .true., none, empty_kwargs(), v, st)
            return
        end if
        select case (ctx%ast%nodes(id)%text)
        case ('not')
            v = bool_value(.not. truth(a))
        case ('-', '+')
            if (.not. is_number(a)) then
                call fail(st, ctx, id, 'unary ' // ctx%ast%nodes(id)%text // &
                          ' needs a number, got ' // kind_label(a)); return
            end if
            if (a%kind == VK_REAL) then
                v = real_value(a%r)
                if (ctx%ast%nodes(id)%text == '-') v%r = -a%r
            else
                v = int_value(a%i)
                if (ctx%ast%nodes(id)%text == '-') v%i = -a%i
            end if
        end select
    end subroutine unary

    recursive subroutine binary(ctx, id, op, a, b, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: op
        type(value_t), intent(in) :: a, b
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        real(dp) :: r
        integer :: code
        type(value_list_t) :: la, lb
        if (a%kind == VK_UNKNOWN .or. b%kind == VK_UNKNOWN) then
            v%kind = VK_UNKNOWN; return
        end if
        if (a%kind == VK_CONCEPT .or. b%kind == VK_CONCEPT) then
            ! a - b on concepts (fields, tables): their __sub__, else b's __rsub__
            if (has_method(ctx, a, operator_name(op, .false.))) then
                call use_attribute(ctx, id, a, operator_name(op, .false.), .true., [b], &
                                   empty_kwargs(), v, st); return
            else if (has_method(ctx, b, operator_name(op, .true.))) then
                call use_attribute(ctx, id, b, operator_name(op, .true.), .true., [a], &
                                   empty_kwargs(), v, st); return
            end if
        end if
        if (is_number(a) .and. is_number(b)) then
            if (a%kind /= VK_REAL .and. b%kind /= VK_REAL .and. op /= '/') then
                call int_binary(ctx, id, op, a%i, b%i, v, st)
                return
            end if
            if (op == '**') then
                call checked_pow(as_real(a), as_real(b), r, code)
            else
                call checked_binary(op, as_real(a), as_real(b), r, code)
            end if
            if (code /= MATH_OK) then
                call fail(st, ctx, id, math_message(code, value_text(a) // ' ' // op // ' ' &
                          // value_text(b))); return
            end if
            v = real_value(r)
            return
        end if
        if (op == '+' .and. a%kind == VK_STR .and. b%kind == VK_STR) then
            if (real(len(a%s), dp) + real(len(b%s), dp) > real(MAX_REPEAT, dp)) then
                call fail(st, ctx, id, 'string too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' characters)'); return
            end if
            v = str_value(a%s // b%s); return
        end if
        if (op == '+' .and. (a%kind == VK_TUPLE .or. a%kind == VK_LIST) .and. &
            b%kind == a%kind) then
            if (nitems(a) + nitems(b) > MAX_REPEAT) then
                call fail(st, ctx, id, kind_label(a) // ' too long (more than ' // &
                          to_text(int(MAX_REPEAT, i4)) // ' items)'); return
            end if
            call count_built(ctx, id, int(nitems(a) + nitems(b), i8), st)
            if (st%failed()) return
            la = unpack_value(a); lb = unpack_value(b)
            call append_values(la%items, lb%items)
            if (a%kind == VK_LIST) then
                v = new_list(ctx, la%items)
            else
                v = sequence_value(a%kind, la%items)
            end if
            return
        end if
        if (op == '*' .and. (a%kind == VK_STR .or. a%kind == VK_TUPLE .or. &
            a%kind == VK_LIST) .and. b%kind == VK_INT) then
            call repeat_value(ctx, id, a, b%i, v, st); return
        end if
        call fail(st, ctx, id, 'unsupported operand types for ' // op // ': ' // &
                  kind_label(a) // ' and ' // kind_label(b))
    end subroutine binary

    subroutine repeat_value(ctx, id, a, n, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: a
        integer(i8), intent(in) :: n
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        integer :: k, length
        type(value_list_t) :: la
        type(value_t), allocatable :: all(:)
        if (a%kind == VK_STR) then
            length = len(a%s)
        else
            length = nitems(a)
        end if
        if (n > 0 .and. real(length, dp) * real(n, dp) > real(MAX_REPEAT, dp)) then
            call fail(st, ctx, id, 'repetition too long (more than 1000000 elements)'); return
        end if
        if (a%kind == VK_STR) then
            v = str_value(repeat(a%s, int(max(n, 0_i8))))
        else
            if (n > 0) call count_built(ctx, id, int(length, i8) * n, st)
            if (st%failed()) return
            la = unpack_value(a)
            allocate (all(0))
            do k = 1, int(n)
                call append_values(all, la%items)
            end do
            if (a%kind == VK_LIST) then
                v = new_list(ctx, all)
            else
                v = sequence_value(a%kind, all)
            end if
        end if
    end subroutine repeat_value

    !> Integer arithmetic with Python's floor division/modulo; overflow is an error.
    subroutine int_binary(ctx, id, op, a, b, v, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: op
        integer(i8), intent(in) :: a, b
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        integer(i8) :: r, q
        integer :: k, code
        real(dp) :: x
        real(dp), parameter :: LIMIT = 9.2e18_dp
        select case (op)
        case ('+', '-', '*')
            if (op == '+') x = real(a, dp) + real(b, dp)
            if (op == '-') x = real(a, dp) - real(b, dp)
            if (op == '*') x = real(a, dp) * real(b, dp)
            if (abs(x) > LIMIT) then
                call fail(st, ctx, id, 'integer overflow in ' // to_text(a) // ' ' // op // &
                          ' ' // to_text(b) // ' (use reals, e.g. 1.0E+20)'); return
            end if
            if (op == '+') r = a + b
            if (op == '-') r = a - b
            if (op == '*') r = a * b
            v = int_value(r)
        case ('//', '%')
            if (b == 0) then
                call fail(st, ctx, id, 'integer division by zero in ' // to_text(a) // ' ' // &
                          op // ' 0'); return
            end if
            q = a / b
            if (mod(a, b) /= 0 .and. ((a < 0) .neqv. (b < 0))) q = q - 1
            if (op == '//') then
                v = int_value(q)
            else
                v = int_value(a - q * b)
            end if
        case ('**')
            if (b < 0) then
                call checked_pow(real(a, dp), real(b, dp), x, code)
                if (code /= MATH_OK) then
                    call fail(st, ctx, id, math_message(code, to_text(a) // ' ** ' // &
                              to_text(b))); return
                end if
                v = real_value(x); return
            end if
            r = 1
            do k = 1, int(min(b, 64_i8))
                if (abs(real(r, dp) * real(a, dp)) > LIMIT) then
                    call fail(st, ctx, id, 'integer overflow in ' // to_text(a) // ' ** ' // &
                              to_text(b) // ' (use reals)'); return
                end if
                r = r * a
            end do
            if (b > 64 .and. abs(a) > 1) then
                call fail(st, ctx, id, 'integer overflow in ' // to_text(a) // ' ** ' // &
                          to_text(b) // ' (use reals)'); return
            end if
            if (b > 64 .and. a == -1 .and. mod(b, 2_i8) == 1) r = -1
            v = int_value(r)
        case default
            call fail(st, ctx, id, 'unsupported operator ' // op)
        end select
    end subroutine int_binary

    recursive subroutine compare_chain(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional :: frame
        type(value_t) :: a, b, r
        type(string_t), allocatable :: ops(:)
        integer :: k, i, j
        character(len=:), allocatable :: text
        text = ctx%ast%nodes(id)%text
        allocate (ops(0))
        i = 1
        do while (i <= len(text))
            j = index(text(i:) // ' ', ' ') + i - 1
            call append_string(ops, text(i:j - 1))
            i = j + 1
        end do
        call eval(ctx, ctx%ast%kid(id, 1), a, st, frame)
        if (st%failed()) return
        v = bool_value(.true.)
        do k = 1, size(ops)
            call eval(ctx, ctx%ast%kid(id, k + 1), b, st, frame)
            if (st%failed()) return
            if (a%kind == VK_UNKNOWN .or. b%kind == VK_UNKNOWN) then
                v%kind = VK_UNKNOWN; return
            end if
            if (a%kind == VK_CONCEPT .or. b%kind == VK_CONCEPT) then
                ! tab.NOM == 'START' on a table: its __eq__ (here a filtered table)
                if (has_method(ctx, a, compare_name(ops(k)%s, .false.))) then
                    call use_attribute(ctx, id, a, compare_name(ops(k)%s, .false.), .true., &
                                       [b], empty_kwargs(), r, st)
                else if (has_method(ctx, b, compare_name(ops(k)%s, .true.))) then
                    call use_attribute(ctx, id, b, compare_name(ops(k)%s, .true.), .true., &
                                       [a], empty_kwargs(), r, st)
                else
                    r = bool_value(compare(ctx, id, ops(k)%s, a, b, st))
                end if
                if (st%failed()) return
                if (size(ops) == 1) then
                    v = r; return
                end if
                if (r%kind == VK_UNKNOWN) then
                    v = r; return
                end if
                if (.not. truth(r)) then
                    v = bool_value(.false.); return
                end if
                a = b
                cycle
            end if
            if (.not. compare(ctx, id, ops(k)%s, a, b, st)) then
                v = bool_value(.false.)
                return
            end if
            if (st%failed()) return
            a = b
        end do
    end subroutine compare_chain

    logical function compare(ctx, id, op, a, b, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: op
        type(value_t), intent(in) :: a, b
        type(status_t), intent(inout) :: st
        integer :: c
        compare = .false.
        if (is_number(a) .and. is_number(b)) then
            if (as_real(a) < as_real(b)) then
                c = -1
            else if (as_real(a) > as_real(b)) then
                c = 1
            else
                c = 0
            end if
        else if (a%kind == VK_STR .and. b%kind == VK_STR) then
            c = 0
            if (llt(a%s, b%s)) c = -1
            if (lgt(a%s, b%s)) c = 1
        else if (op == '==' .or. op == '!=') then
            c = 1
            if (a%kind == b%kind .and. a%kind == VK_CONCEPT) then
                if (associated(a%obj, b%obj)) c = 0
            end if
            if (a%kind == VK_NONE .and. b%kind == VK_NONE) c = 0
        else
            call fail(st, ctx, id, 'cannot order ' // kind_label(a) // ' and ' // &
                      kind_label(b)); return
        end if
        select case (op)
        case ('<')
            compare = c < 0
        case ('<=')
            compare = c <= 0
        case ('>')
            compare = c > 0
        case ('>=')
            compare = c >= 0
        case ('==')
            compare = c == 0
        case ('!=')
            compare = c /= 0
        end select
    end function compare

    subroutine fail(st, ctx, id, message)
        type(status_t), intent(inout) :: st
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: message
        if (st%failed()) return
        call set_error(st, STATUS_DECK_ERROR, message, file=node_file(ctx, id), &
                       line=ctx%ast%nodes(id)%line, column=ctx%ast%nodes(id)%col)
    end subroutine fail

end module deck_interpreter
