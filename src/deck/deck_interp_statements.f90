!> The deck evaluator (deck_interpreter), its statements: reading and parsing the files of a
!> session, running their statements (assignments to names, subscripts and tuples of
!> targets, augmented assignment, def, if, for and while loops with break, continue and
!> else, del, assert, raise), and collecting the lists and dicts nothing refers to any more
!> between statements of the top level.
submodule(deck_interpreter) deck_interp_statements
    use system_error, only: readable_errno, errno_text
    use status, only: add_context, STATUS_IO_ERROR
    use deck_lexer, only: check_bytes
    use deck_parser, only: parse_deck
    use deck_sequence, only: range_steps, slice_positions
    use run_context, only: SCOPE_SESSION
    implicit none

contains

    !> Reads the deck file of ctx, checks its bytes, keeps its lines and parses it: the
    !> first command file of the session.
    !>  st : out, STATUS_IO_ERROR if unreadable; STATUS_DECK_ERROR located for bad content
    module procedure load_deck
        character(len=:), allocatable :: text
        call read_source_text(ctx%deck_path, 'the deck', text, st)
        if (st%failed()) return
        call deck_from_text(ctx, text, st)
    end procedure load_deck

    !> Reads a whole text file.
    !>  path : in;  what : in, what it is for messages ('the deck', 'the module m')
    !>  text : out;  st : out, STATUS_IO_ERROR naming the file when it cannot be read
    module procedure read_source_text
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
    end procedure read_source_text

    !> Parses deck text into ctx as its first command file (also used by tests without
    !> a file).
    module procedure deck_from_text
        integer :: k
        call load_source(ctx, text, ctx%deck_name, ctx%deck_dir, '', k, st)
        if (st%failed()) return
        ctx%ncommand_file = max(ctx%ncommand_file, 1)
        call ctx%begin_file(1)
    end procedure deck_from_text

    !> Checks, splits and parses the text of one source file and registers it in ctx.
    !>  name : in, the file as named in messages;  dir : in, its folder ('' or ending '/')
    !>  module : in, '' for a command file, else the module name
    !>  k : out, its source index;  st : out, located errors (bytes, syntax, empty file)
    module procedure load_source
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
    end procedure load_source

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

    !> Evaluates the command files of the session in order (one pass). Each file after the
    !> first starts with the earlier files' names put aside: POURSUITE() brings them back.
    !> The .mess shows where each file starts.
    !>  st : out, the first error, located
    module procedure evaluate_session
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
    end procedure evaluate_session

    !> Evaluates every top-level statement of the parsed deck (one pass).
    !>  st : out, the first error, located
    module procedure evaluate_deck
        integer :: k, stmt
        do k = 1, ctx%ast%nkids(ctx%ast%root)
            stmt = ctx%ast%kid(ctx%ast%root, k)
            if (ctx%finished .and. fin_again(stmt)) then
                ! Code_Aster's FIN returns at once when the session is already closed
                ! (Closer.run): a second FIN() has no effect
                call ctx%write_mess('  -- FIN again (line ' // &
                    to_text(int(ctx%ast%nodes(stmt)%line, i4)) // '): no effect')
                cycle
            end if
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
        call flush_print(ctx)
    contains
        !> The statement is `FIN(...)` again.
        logical function fin_again(id)
            integer, intent(in) :: id
            integer :: call_node, callee
            fin_again = .false.
            if (ctx%ast%nodes(id)%kind /= N_EXPR .or. ctx%ast%nkids(id) /= 1) return
            call_node = ctx%ast%kid(id, 1)
            if (ctx%ast%nodes(call_node)%kind /= N_CALL) return
            callee = ctx%ast%kid(call_node, 1)
            fin_again = ctx%ast%nodes(callee)%kind == N_NAME .and. &
                ctx%ast%nodes(callee)%text == 'FIN'
        end function fin_again
    end procedure evaluate_deck

    !> A print(..., end='') line still open goes to the .mess at the end of a file.
    subroutine flush_print(ctx)
        type(run_context_t), intent(inout) :: ctx
        if (len(ctx%print_line) == 0) return
        call ctx%write_mess(ctx%print_line)
        ctx%print_line = ''
    end subroutine flush_print

    !> Ends the check pass at statement or expression `id`: the flow of the deck depends
    !> there on a value known only when it runs (a condition or a loop on a table's cell).
    !> The rest is validated as it runs (every command is validated before it runs).
    module procedure stop_check
        if (.not. ctx%checking .or. ctx%check_stopped) return
        ctx%check_stopped = .true.
        ctx%check_stop_file = node_file(ctx, id)
        ctx%check_stop_line = ctx%ast%nodes(id)%line
    end procedure stop_check

    ! ---- statements -------------------------------------------------------------------------

    module procedure exec_statement
        type(value_t) :: v
        integer :: k, nk
        type(node_t) :: node
        if (ctx%check_stopped) return
        if (.not. present(frame) .and. ctx%gc_hold == 0) call collect_if_due(ctx)
        node = ctx%ast%nodes(id)       ! a copy: evaluation may grow the AST (FORMULE VALE)
        nk = size(node%kids)
        select case (node%kind)
        case (N_ASSIGN)
            call eval(ctx, node%kids(1), v, st, frame, target=node%text)
            if (st%failed()) return
            call bind_name(ctx, id, node%text, v, frame)
        case (N_ASSIGN_MULTI)
            call eval(ctx, node%kids(nk), v, st, frame, target=single_name())
            if (st%failed()) return
            do k = 1, nk - 1                        ! a = b = v binds left to right
                call assign_target(ctx, node%kids(k), v, st, frame)
                if (st%failed()) return
            end do
        case (N_AUGASSIGN)
            call exec_augmented(ctx, id, st, frame)
        case (N_EXPR)
            call eval(ctx, node%kids(1), v, st, frame)
        case (N_DEF)
            call def_value(ctx, id, v, st, frame)
            if (st%failed()) return
            call bind_name(ctx, id, node%text, v, frame)
        case (N_FOR)
            call exec_for(ctx, id, st, frame)
        case (N_WHILE)
            call exec_while(ctx, id, st, frame)
        case (N_BREAK)
            ctx%loop_control = LOOP_BREAK
        case (N_CONTINUE)
            ctx%loop_control = LOOP_CONTINUE
        case (N_IMPORT, N_FROM_IMPORT)
            call exec_import(ctx, id, st, frame)
        case (N_IF)
            call eval(ctx, node%kids(1), v, st, frame)
            if (st%failed()) return
            if (v%kind == VK_UNKNOWN) then
                call stop_check(ctx, id); return
            end if
            if (is_true(ctx, v)) then
                call exec_block(ctx, node%kids(2), st, frame)
            else if (nk > 2) then
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
        case (N_DEL)
            do k = 1, nk
                call delete_target(ctx, node%kids(k), st, frame)
                if (st%failed()) return
            end do
        case (N_ASSERT)
            call exec_assert(ctx, id, st, frame)
        case (N_RAISE)
            call exec_raise(ctx, id, st, frame)
        case (N_PASS)
        case default
            k = node%kind
            call fail(st, ctx, id, 'unexpected statement (kind ' // to_text(int(k, i4)) // ')')
        end select
    contains
        !> The name a command's result gets in the .mess: the one target of a = b = CMD()
        !> when all targets are that name, else ''.
        function single_name() result(name)
            character(len=:), allocatable :: name
            name = ''
            if (ctx%ast%nodes(node%kids(1))%kind == N_NAME) &
                name = ctx%ast%nodes(node%kids(1))%text
        end function single_name
    end procedure exec_statement

    module procedure exec_block
        integer :: k
        do k = 1, ctx%ast%nkids(block)
            call exec_statement(ctx, ctx%ast%kid(block, k), st, frame)
            if (st%failed() .or. ctx%check_stopped) return
            if (ctx%loop_control /= 0) return         ! break/continue: the loop decides
            if (present(frame)) then
                if (frame%returned) return
            end if
        end do
    end procedure exec_block

    !> A def statement's value: the function, its defaults evaluated now (as Python does:
    !> a list default is one list shared by the calls), kept in its tree.
    subroutine def_value(ctx, id, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t), allocatable :: defaults(:)
        integer :: k, p
        allocate (defaults(0))
        do k = 1, ctx%ast%nkids(id) - 1
            p = ctx%ast%kid(id, k)
            if (ctx%ast%nodes(p)%kind /= N_NAME .or. ctx%ast%nkids(p) == 0) cycle
            call append_value(defaults, value_t())
            call eval(ctx, ctx%ast%kid(p, 1), defaults(size(defaults)), st, frame)
            if (st%failed()) return
        end do
        v = function_value(ctx, id, ctx%ast%nodes(id)%text, defaults, frame)
        v%line = ctx%ast%nodes(id)%line; v%col = ctx%ast%nodes(id)%col
    end subroutine def_value

    !> Binds `name` to v: a local of the def or comprehension being run, else a name of the
    !> namespace of statement `id`'s file (the session's, or a module's).
    module procedure bind_name
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
    end procedure bind_name

    !> Assigns v to a target: a name, x[i] (list, dict, concept), x[i:j] (list), or a tuple
    !> or list of targets (v unpacked: any sequence of as many items).
    module procedure assign_target
        type(value_t) :: container, index
        type(value_t), allocatable :: items(:)
        integer :: k, n
        select case (ctx%ast%nodes(target)%kind)
        case (N_NAME)
            call bind_name(ctx, target, ctx%ast%nodes(target)%text, v, frame)
        case (N_TUPLE, N_LIST)
            if (v%kind == VK_UNKNOWN) then
                do k = 1, ctx%ast%nkids(target)
                    call assign_target(ctx, ctx%ast%kid(target, k), v, st, frame)
                end do
                return
            end if
            call iterate(ctx, target, v, items, st)
            if (st%failed()) return
            n = ctx%ast%nkids(target)
            if (size(items) /= n) then
                if (size(items) > n) then
                    call fail(st, ctx, target, 'too many values to unpack (expected ' // &
                        to_text(n) // ', got ' // to_text(size(items)) // ')')
                else
                    call fail(st, ctx, target, 'not enough values to unpack (expected ' // &
                        to_text(n) // ', got ' // to_text(size(items)) // ')')
                end if
                return
            end if
            do k = 1, n
                call assign_target(ctx, ctx%ast%kid(target, k), items(k), st, frame)
                if (st%failed()) return
            end do
        case (N_INDEX)
            call eval(ctx, ctx%ast%kid(target, 1), container, st, frame)
            if (st%failed()) return
            call eval(ctx, ctx%ast%kid(target, 2), index, st, frame)
            if (st%failed()) return
            call set_item(ctx, target, container, index, v, st)
        case (N_SLICE)
            call assign_slice(ctx, target, v, st, frame)
        case (N_ATTR)
            call eval(ctx, ctx%ast%kid(target, 1), container, st, frame)
            if (st%failed()) return
            if (container%kind == VK_UNKNOWN) return
            call fail(st, ctx, target, 'cannot set the attribute ' // ctx%ast%nodes(target)%text &
                // ' of ' // kind_label(container) // ' in the deck language')
        case default
            call fail(st, ctx, target, 'cannot assign to this expression')
        end select
    end procedure assign_target

    !> L[i:j:k] = iterable on a list: Python's slice assignment (a step other than 1 needs
    !> as many items as the slice selects).
    subroutine assign_slice(ctx, target, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: target
        type(value_t), intent(in) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: container
        type(value_t), allocatable :: items(:), old(:), new(:)
        integer :: first, step, count, k, n
        call eval(ctx, ctx%ast%kid(target, 1), container, st, frame)
        if (st%failed()) return
        if (container%kind == VK_UNKNOWN) return
        if (container%kind /= VK_LIST) then
            call fail(st, ctx, target, 'slice assignment needs a list, got ' // &
                      kind_label(container)); return
        end if
        call slice_of(ctx, target, ctx%heap%length(container%i), first, step, count, st, frame)
        if (st%failed()) return
        call iterate(ctx, target, v, items, st)
        if (st%failed()) return
        old = ctx%heap%items_of(container%i)
        n = size(old)
        if (step == 1) then
            allocate (new(n - count + size(items)))
            new(1:first - 1) = old(1:first - 1)
            if (size(items) > 0) new(first:first + size(items) - 1) = items
            if (first + count <= n) new(first + size(items):) = old(first + count:n)
        else
            if (size(items) /= count) then
                call fail(st, ctx, target, 'attempt to assign a sequence of ' // &
                    to_text(size(items)) // ' items to an extended slice of ' // to_text(count)); return
            end if
            new = old
            do k = 1, count
                new(first + (k - 1) * step) = items(k)
            end do
        end if
        call ctx%heap%set_items(container%i, new)
        call check_heap(ctx, target, st)
    end subroutine assign_slice

    !> first, step, count of the slice node `id` (N_SLICE) over n items.
    subroutine slice_of(ctx, id, n, first, step, count, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id, n
        integer, intent(out) :: first, step, count
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        character(len=:), allocatable :: parts, message
        logical :: given(3)
        integer(i8) :: bounds(3)
        type(value_t) :: b
        integer :: k, j
        first = 1; step = 1; count = 0
        parts = ctx%ast%nodes(id)%text
        given = .false.; bounds = 0; j = 1
        do k = 1, 3
            if (parts(k:k) /= '1') cycle
            j = j + 1
            call eval(ctx, ctx%ast%kid(id, j), b, st, frame)
            if (st%failed()) return
            if (b%kind == VK_NONE) cycle
            if (b%kind /= VK_INT .and. b%kind /= VK_BOOL) then
                call fail(st, ctx, ctx%ast%kid(id, j), 'slice bounds must be integers, got ' &
                          // kind_label(b)); return
            end if
            given(k) = .true.; bounds(k) = b%i
        end do
        call slice_positions(n, given, bounds, first, step, count, message)
        if (len(message) > 0) call fail(st, ctx, id, message)
    end subroutine slice_of

    !> del NAME | del x[i] | del x[i:j]
    recursive subroutine delete_target(ctx, target, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: target
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: container, index, old
        type(value_t), allocatable :: items(:), keep(:)
        character(len=:), allocatable :: name, message
        integer :: k, first, step, count, n
        logical, allocatable :: drop(:)
        select case (ctx%ast%nodes(target)%kind)
        case (N_NAME)
            name = ctx%ast%nodes(target)%text
            if (present(frame)) then
                do k = 1, frame%n
                    if (frame%names(k)%s == name) then
                        frame%names(k:frame%n - 1) = frame%names(k + 1:frame%n)
                        frame%values(k:frame%n - 1) = frame%values(k + 1:frame%n)
                        frame%n = frame%n - 1
                        frame%names = frame%names(1:frame%n)
                        frame%values = frame%values(1:frame%n)
                        return
                    end if
                end do
            else if (ctx%delete_symbol(name, scope_of(ctx, target))) then
                return
            end if
            call fail(st, ctx, target, 'del: name ' // name // ' is not defined')
        case (N_INDEX)
            call eval(ctx, ctx%ast%kid(target, 1), container, st, frame)
            if (st%failed()) return
            call eval(ctx, ctx%ast%kid(target, 2), index, st, frame)
            if (st%failed()) return
            select case (container%kind)
            case (VK_LIST)
                if (index%kind /= VK_INT .and. index%kind /= VK_BOOL) then
                    call fail(st, ctx, target, 'a list index must be an integer, got ' // &
                              kind_label(index)); return
                end if
                call get_item(ctx, target, container, index, old, st)   ! the range check
                if (st%failed()) return
                k = int(index%i)
                if (k < 0) k = k + ctx%heap%length(container%i)
                call ctx%heap%remove_at(container%i, k + 1)
            case (VK_DICT)
                call get_item(ctx, target, container, index, old, st)   ! the KeyError
                if (st%failed()) return
                call ctx%heap%dict_delete(container%i, ctx%heap%dict_find(container%i, index))
            case (VK_UNKNOWN)
            case default
                call fail(st, ctx, target, 'del x[i] needs a list or a dict, got ' // &
                          kind_label(container))
            end select
        case (N_SLICE)
            call eval(ctx, ctx%ast%kid(target, 1), container, st, frame)
            if (st%failed()) return
            if (container%kind /= VK_LIST) then
                call fail(st, ctx, target, 'del x[i:j] needs a list, got ' // &
                          kind_label(container)); return
            end if
            n = ctx%heap%length(container%i)
            call slice_of(ctx, target, n, first, step, count, st, frame)
            if (st%failed()) return
            items = ctx%heap%items_of(container%i)
            allocate (drop(n))
            drop = .false.
            do k = 1, count
                drop(first + (k - 1) * step) = .true.
            end do
            allocate (keep(0))
            do k = 1, n
                if (.not. drop(k)) call append_value(keep, items(k))
            end do
            call ctx%heap%set_items(container%i, keep)
        case default
            message = 'del takes names and subscripts'
            call fail(st, ctx, target, message)
        end select
    end subroutine delete_target

    !> target op= value: in place for a list (L += iterable extends it, L *= n repeats it,
    !> as Python's), else target = target op value; x[i] op= v reads x and i once.
    subroutine exec_augmented(ctx, id, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        integer :: target, value_node
        type(value_t) :: current, value, result, container, index
        character(len=:), allocatable :: op
        op = ctx%ast%nodes(id)%text
        target = ctx%ast%kid(id, 1)
        value_node = ctx%ast%kid(id, 2)
        select case (ctx%ast%nodes(target)%kind)
        case (N_NAME)
            call eval(ctx, target, current, st, frame)
            if (st%failed()) return
            call eval(ctx, value_node, value, st, frame)
            if (st%failed()) return
            call binary(ctx, id, op, current, value, result, st, in_place=.true.)
            if (st%failed()) return
            call bind_name(ctx, target, ctx%ast%nodes(target)%text, result, frame)
        case (N_INDEX)
            call eval(ctx, ctx%ast%kid(target, 1), container, st, frame)
            if (st%failed()) return
            call eval(ctx, ctx%ast%kid(target, 2), index, st, frame)
            if (st%failed()) return
            call get_item(ctx, target, container, index, current, st)
            if (st%failed()) return
            call eval(ctx, value_node, value, st, frame)
            if (st%failed()) return
            call binary(ctx, id, op, current, value, result, st, in_place=.true.)
            if (st%failed()) return
            call set_item(ctx, target, container, index, result, st)
        case default
            call fail(st, ctx, target, 'cannot use ' // op // '= on this target')
        end select
    end subroutine exec_augmented

    !> assert CONDITION[, MESSAGE]: a located error when the condition is false.
    subroutine exec_assert(ctx, id, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: cond, message
        call eval(ctx, ctx%ast%kid(id, 1), cond, st, frame)
        if (st%failed()) return
        if (cond%kind == VK_UNKNOWN) then
            call stop_check(ctx, id); return
        end if
        if (is_true(ctx, cond)) return
        if (ctx%ast%nkids(id) > 1) then
            call eval(ctx, ctx%ast%kid(id, 2), message, st, frame)
            if (st%failed()) return
            call fail(st, ctx, id, 'assertion failed: ' // text_of(ctx, message, .false.))
        else
            call fail(st, ctx, id, 'assertion failed')
        end if
    end subroutine exec_assert

    !> raise [EXCEPTION]: the run stops with the exception's text, located at the raise.
    subroutine exec_raise(ctx, id, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: exc
        if (ctx%ast%nkids(id) == 0) then
            call fail(st, ctx, id, 'raise: the deck stops here'); return
        end if
        call eval(ctx, ctx%ast%kid(id, 1), exc, st, frame)
        if (st%failed()) return
        if (exc%kind == VK_UNKNOWN) then
            call stop_check(ctx, id); return
        end if
        call fail(st, ctx, id, 'raise: ' // text_of(ctx, exc, .false.))
    end subroutine exec_raise

    ! ---- loops ------------------------------------------------------------------------------

    !> for TARGET in SEQUENCE: body [else: ...]. range(...) is counted, never built; a list
    !> is walked to its current end at every step (a list appended to in the body is walked
    !> to its new end, as in Python); other sequences (tuples, strings, dicts, ...) are
    !> walked as they were when the loop began. The else block runs when no break ended it.
    !> Every iteration counts against MAX_LOOP_ITERATIONS and polls the time limit.
    recursive subroutine exec_for(ctx, id, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        integer :: target, seq, body, k
        integer(i8) :: first, step, count, j
        type(value_t) :: v
        type(value_t), allocatable :: items(:)
        logical :: broke
        target = ctx%ast%kid(id, 1)
        seq = ctx%ast%kid(id, 2)
        body = ctx%ast%kid(id, 3)
        broke = .false.
        if (is_range_call(ctx, seq, frame)) then
            call range_bounds(ctx, seq, first, step, count, st, frame)
            if (st%failed() .or. ctx%check_stopped) return
            do j = 1, count
                call next_iteration(ctx, id, st)
                if (st%failed()) return
                call assign_target(ctx, target, int_value(first + (j - 1) * step), st, frame)
                if (st%failed()) return
                if (body_done(broke)) exit
            end do
        else
            call eval(ctx, seq, v, st, frame)
            if (st%failed()) return
            if (v%kind == VK_UNKNOWN) then
                call stop_check(ctx, id); return
            end if
            if (v%kind /= VK_LIST) then
                call iterate(ctx, seq, v, items, st)
                if (st%failed()) return
                v = sequence_value(VK_TUPLE, items)   ! what the loop walks, a root
            end if
            call push_loop(ctx, v)
            k = 0
            do
                k = k + 1
                if (v%kind == VK_LIST) then
                    if (k > ctx%heap%length(v%i)) exit
                else
                    if (k > size(items)) exit
                end if
                call next_iteration(ctx, id, st)
                if (st%failed()) exit
                if (v%kind == VK_LIST) then
                    call assign_target(ctx, target, ctx%heap%get(v%i, k), st, frame)
                else
                    call assign_target(ctx, target, items(k), st, frame)
                end if
                if (st%failed()) exit
                if (body_done(broke)) exit
            end do
            ctx%nloop = ctx%nloop - 1
        end if
        if (st%failed() .or. broke .or. ctx%check_stopped) return
        if (present(frame)) then
            if (frame%returned) return
        end if
        if (ctx%ast%nkids(id) > 3) call exec_block(ctx, ctx%ast%kid(id, 4), st, frame)
    contains
        !> Runs the body once; true when the loop must stop (break, return, error).
        recursive logical function body_done(broken) result(done)
            logical, intent(inout) :: broken
            call exec_block(ctx, body, st, frame)
            broken = ctx%loop_control == LOOP_BREAK
            done = st%failed() .or. broken .or. ctx%check_stopped
            ctx%loop_control = 0
            if (present(frame)) done = done .or. frame%returned
        end function body_done
    end subroutine exec_for

    !> while CONDITION: body [else: ...]
    recursive subroutine exec_while(ctx, id, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: cond
        logical :: broke
        broke = .false.
        do
            call eval(ctx, ctx%ast%kid(id, 1), cond, st, frame)
            if (st%failed()) return
            if (cond%kind == VK_UNKNOWN) then
                call stop_check(ctx, id); return
            end if
            if (.not. is_true(ctx, cond)) exit
            call next_iteration(ctx, id, st)
            if (st%failed()) return
            call exec_block(ctx, ctx%ast%kid(id, 2), st, frame)
            broke = ctx%loop_control == LOOP_BREAK
            ctx%loop_control = 0
            if (st%failed() .or. broke .or. ctx%check_stopped) return
            if (present(frame)) then
                if (frame%returned) return
            end if
        end do
        if (ctx%ast%nkids(id) > 2) call exec_block(ctx, ctx%ast%kid(id, 3), st, frame)
    end subroutine exec_while

    !> Counts one iteration against MAX_LOOP_ITERATIONS and polls the time limit.
    module procedure next_iteration
        ctx%iterations = ctx%iterations + 1
        if (ctx%iterations > MAX_LOOP_ITERATIONS) then
            call fail(st, ctx, id, 'more than ' // to_text(MAX_LOOP_ITERATIONS) // &
                ' loop iterations in all (the limit MAX_LOOP_ITERATIONS keeps a deck from ' // &
                'hanging parasol; is a loop endless?)'); return
        end if
        call ctx%deadline%check('the loop at ' // node_where(ctx, id), st)
        call add_context(st, file=node_file(ctx, id), line=int(ctx%ast%nodes(id)%line), &
                         column=int(ctx%ast%nodes(id)%col))
    end procedure next_iteration

    !> True when node `seq` is a call of the built-in range (not a deck name `range`).
    logical function is_range_call(ctx, seq, frame)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: seq
        type(frame_t), intent(in), optional :: frame
        integer :: callee, k
        is_range_call = .false.
        if (ctx%ast%nodes(seq)%kind /= N_CALL) return
        callee = ctx%ast%kid(seq, 1)
        if (ctx%ast%nodes(callee)%kind /= N_NAME) return
        if (ctx%ast%nodes(callee)%text /= 'range') return
        do k = 2, ctx%ast%nkids(seq)          ! range(*args), range(n=...): the general call
            if (any(ctx%ast%nodes(ctx%ast%kid(seq, k))%kind == [N_STARRED, N_DSTAR, &
                    N_KWARG])) return
        end do
        if (ctx%find_symbol('range', scope_of(ctx, seq)) > 0) return
        if (present(frame)) then
            do k = 1, frame%n
                if (frame%names(k)%s == 'range') return
            end do
        end if
        is_range_call = .true.
    end function is_range_call

    !> range(stop) | range(start, stop[, step]) with integers: first value, step, count.
    recursive subroutine range_bounds(ctx, seq, first, step, count, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: seq
        integer(i8), intent(out) :: first, step, count
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t) :: args(3)
        integer(i8) :: b(3)
        integer :: k, n
        character(len=:), allocatable :: message
        first = 0; step = 1; count = 0
        n = ctx%ast%nkids(seq) - 1
        if (n < 1 .or. n > 3) then
            call fail(st, ctx, seq, 'range() takes 1 to 3 integers: range(stop), ' // &
                      'range(start, stop) or range(start, stop, step)'); return
        end if
        do k = 1, n
            call eval(ctx, ctx%ast%kid(seq, k + 1), args(k), st, frame)
            if (st%failed()) return
            if (args(k)%kind == VK_UNKNOWN) then
                call stop_check(ctx, seq); return
            end if
            if (args(k)%kind /= VK_INT .and. args(k)%kind /= VK_BOOL) then
                call fail(st, ctx, seq, 'range() takes integers, got ' // &
                          kind_label(args(k)) // ' (use int(...))'); return
            end if
            b(k) = args(k)%i
        end do
        if (n == 1) then
            b(2) = b(1); b(1) = 0
        end if
        if (n == 3) step = b(3)
        first = b(1)
        call range_steps(b(1), b(2), step, count, message)
        if (len(message) > 0) call fail(st, ctx, seq, message)
    end subroutine range_bounds

    !> Pushes the sequence a running loop walks (a root of the collection).
    subroutine push_loop(ctx, v)
        type(run_context_t), intent(inout) :: ctx
        type(value_t), intent(in) :: v
        type(value_t), allocatable :: bigger(:)
        integer :: k
        if (ctx%nloop == size(ctx%loops)) then
            allocate (bigger(2 * ctx%nloop))
            do k = 1, ctx%nloop
                bigger(k) = ctx%loops(k)
            end do
            call move_alloc(bigger, ctx%loops)
        end if
        ctx%nloop = ctx%nloop + 1
        ctx%loops(ctx%nloop) = v
    end subroutine push_loop

    ! ---- collection -------------------------------------------------------------------------

    !> Frees the lists and dicts nothing refers to when the heap has grown enough since the
    !> last collection. Called between statements where no def or comprehension runs: then
    !> every live reference is in a root (the names of every namespace, the names put aside
    !> for POURSUITE, the sequences of the running loops).
    subroutine collect_if_due(ctx)
        type(run_context_t), intent(inout) :: ctx
        integer :: k
        if (ctx%heap%live_items - ctx%heap%items_at_last_sweep < COLLECT_AFTER_ITEMS) return
        do k = 1, ctx%nsymbol
            call ctx%heap%mark(ctx%symbols(k)%value)
        end do
        do k = 1, ctx%nstash
            call ctx%heap%mark(ctx%stash(k)%value)
        end do
        do k = 1, ctx%nloop
            call ctx%heap%mark(ctx%loops(k))
        end do
        call ctx%heap%sweep()
    end subroutine collect_if_due

end submodule deck_interp_statements
