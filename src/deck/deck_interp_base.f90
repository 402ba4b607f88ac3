!> What the parts of the deck evaluator (deck_interpreter and its submodules) share: its
!> bounds, the frame of a def call or a comprehension, located errors, and small helpers on
!> values (keyword arguments, the heap's limits, function values).
module deck_interp_base
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_ast
    use deck_value
    use run_context, only: run_context_t
    implicit none
    private

    !> Deepest chain of def calls and comprehensions (deep recursion is not deck practice).
    integer, parameter, public :: MAX_CALL_DEPTH = 50
    !> Longest string, tuple or list built by an operation (+, *, join, list(...)).
    integer, parameter, public :: MAX_REPEAT = 1000000
    !> Loop iterations in one pass over a session: far beyond deck practice (loops over
    !> groups, cells or instants), and a bound so that no deck hangs parasol.
    integer(i8), parameter, public :: MAX_LOOP_ITERATIONS = 1000000_i8
    !> Commands the check pass validates: beyond, it stops (stop_check) and the rest is
    !> validated as the deck runs, each command before it runs. Validating a command costs
    !> ~45 us (Release; ~5 x in Debug), so a loop of a million iterations with commands in
    !> its body would otherwise keep the check pass busy for minutes before the first
    !> command runs (fuzz seed 802, case 621); Code_Aster's own decks validate a few
    !> thousand.
    integer, parameter, public :: MAX_CHECKED_COMMANDS = 20000
    !> Sequence items copied in one pass (+, *, slices, comprehensions, list(...) copy
    !> their items): a bound on the work a deck can ask for (a few seconds).
    integer(i8), parameter, public :: MAX_BUILT_ITEMS = 20000000_i8
    !> Modules imported inside one another.
    integer, parameter, public :: MAX_IMPORT_DEPTH = 20
    !> Lists and dicts nested inside one another when their text is written (str, print).
    integer, parameter, public :: MAX_TEXT_DEPTH = 100
    !> Items the heap may gain between two collections before one is due (deck_heap).
    integer(i8), parameter, public :: COLLECT_AFTER_ITEMS = 200000_i8
    !> Math functions beyond deck_math's (math.NAME, or NAME after from math import *).
    character(len=*), parameter, public :: MATH_EXTRA = ' fabs hypot degrees radians isclose '
    !> ctx%loop_control after break / continue.
    integer, parameter, public :: LOOP_BREAK = 1, LOOP_CONTINUE = 2

    !> Local variables of one def call or one comprehension. A comprehension's frame sees
    !> the names of the frame it is evaluated in (`enclosing`), as Python's nested scopes.
    type, public :: frame_t
        type(string_t), allocatable :: names(:)
        type(value_t), allocatable :: values(:)
        integer :: n = 0
        integer :: depth = 0
        logical :: returned = .false.
        type(value_t) :: ret
        logical :: comprehension = .false.
        type(frame_t), pointer :: enclosing => null()
    end type frame_t

    public :: fail, node_where, node_file, scope_of, empty_kwargs, new_list, check_heap, &
        count_built, kwarg, only_kwargs, function_value, holds_unknown, arity, want_text

contains

    !> A located error at AST node `id` (the first error is kept).
    subroutine fail(st, ctx, id, message)
        type(status_t), intent(inout) :: st
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: message
        if (st%failed()) return
        ! Once the check pass has stopped (stop_check), the values it computes stand for
        ! values of the run: what they would refuse is checked when the deck runs.
        if (ctx%checking .and. ctx%check_stopped) return
        call set_error(st, STATUS_DECK_ERROR, message, file=node_file(ctx, id), &
                       line=ctx%ast%nodes(id)%line, column=ctx%ast%nodes(id)%col)
    end subroutine fail

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

    !> The namespace of the code of node `id` (SCOPE_SESSION or a module's).
    pure integer function scope_of(ctx, id)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        scope_of = ctx%scope_of_file(int(ctx%ast%nodes(id)%file))
    end function scope_of

    !> No keyword arguments (a VK_FACTOR without items).
    pure function empty_kwargs() result(v)
        type(value_t) :: v
        v%kind = VK_FACTOR
    end function empty_kwargs

    !> A new list of the heap holding items (counted against MAX_LIVE_ITEMS by the caller's
    !> check_heap).
    function new_list(ctx, items) result(v)
        type(run_context_t), intent(inout) :: ctx
        type(value_t), intent(in) :: items(:)
        type(value_t) :: v
        v = ctx%heap%new_list(items)
    end function new_list

    !> A located error when the live lists and dicts hold more than MAX_LIVE_ITEMS items.
    subroutine check_heap(ctx, id, st)
        use deck_heap, only: MAX_LIVE_ITEMS
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        type(status_t), intent(inout) :: st
        if (.not. ctx%heap%over_limit()) return
        call fail(st, ctx, id, 'more than ' // to_text(MAX_LIVE_ITEMS) // ' items in the ' // &
            'lists and dicts of the deck (the limit MAX_LIVE_ITEMS bounds the memory a deck ' // &
            'may use; is a list growing without end?)')
    end subroutine check_heap

    !> Counts n items copied against MAX_BUILT_ITEMS.
    subroutine count_built(ctx, id, n, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        integer(i8), intent(in) :: n
        type(status_t), intent(inout) :: st
        ctx%built = ctx%built + n
        if (ctx%built > MAX_BUILT_ITEMS) call fail(st, ctx, id, 'more than ' // &
            to_text(MAX_BUILT_ITEMS) // ' sequence items copied in all (the limit ' // &
            'MAX_BUILT_ITEMS keeps a deck from hanging parasol; +, *, slices and ' // &
            'comprehensions copy the sequence)')
    end subroutine count_built

    !> The keyword argument `name` of kwargs (a VK_FACTOR), found = .false. when absent.
    subroutine kwarg(kwargs, name, v, found)
        type(value_t), intent(in) :: kwargs
        character(len=*), intent(in) :: name
        type(value_t), intent(out) :: v
        logical, intent(out) :: found
        type(value_list_t) :: list
        integer :: k
        found = .false.
        if (nitems(kwargs) == 0) return
        list = unpack_value(kwargs)
        do k = 1, size(list%items)
            if (list%keys(k)%s == name) then
                v = list%items(k)
                found = .true.
                return
            end if
        end do
    end subroutine kwarg

    !> Error unless every keyword of kwargs is one of `allowed` (blank-separated; '*' any).
    subroutine only_kwargs(ctx, id, what, kwargs, allowed, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: what
        type(value_t), intent(in) :: kwargs
        character(len=*), intent(in) :: allowed
        type(status_t), intent(inout) :: st
        type(value_list_t) :: list
        integer :: k
        if (nitems(kwargs) == 0 .or. allowed == '*') return
        list = unpack_value(kwargs)
        do k = 1, size(list%keys)
            if (index(' ' // allowed // ' ', ' ' // list%keys(k)%s // ' ') == 0) then
                if (len_trim(allowed) == 0) then
                    call fail(st, ctx, id, what // ' takes no keyword argument (got ' // &
                              list%keys(k)%s // '=)')
                else
                    call fail(st, ctx, id, what // ' got an unexpected keyword argument ' // &
                              list%keys(k)%s // ' (its keywords: ' // trim(allowed) // ')')
                end if
                return
            end if
        end do
    end subroutine only_kwargs

    !> The value of a def or a lambda (node id): VK_DEF, s = its name, i = its node, and in
    !> its tree the tuple of its parameters' defaults (evaluated where it is defined, as
    !> Python does) and a _F of the names of the frames around it (a def or lambda made
    !> inside a def or a comprehension sees them: Python's closures, taken when it is made).
    function function_value(ctx, id, name, defaults, frame) result(v)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: defaults(:)
        type(frame_t), intent(in), optional, target :: frame
        type(value_t) :: v
        type(value_list_t) :: captured
        type(frame_t), pointer :: f
        integer :: k, j
        logical :: seen
        allocate (captured%items(0), captured%keys(0), captured%key_line(0), &
                  captured%key_col(0))
        if (present(frame)) then
            f => frame
            do while (associated(f))
                do k = f%n, 1, -1
                    seen = .false.
                    do j = 1, size(captured%keys)
                        if (captured%keys(j)%s == f%names(k)%s) seen = .true.
                    end do
                    if (seen) cycle
                    call append_value(captured%items, f%values(k))
                    call append_string(captured%keys, f%names(k)%s)
                    captured%key_line = [captured%key_line, 0]
                    captured%key_col = [captured%key_col, 0]
                end do
                if (.not. f%comprehension) exit
                f => f%enclosing
            end do
        end if
        v = sequence_value(VK_TUPLE, values_of(sequence_value(VK_TUPLE, defaults), &
                                               pack_values(VK_FACTOR, captured)))
        v%kind = VK_DEF
        v%s = name
        v%i = id
        v%line = ctx%ast%nodes(id)%line; v%col = ctx%ast%nodes(id)%col
    end function function_value

    !> True when v is, or (a tuple, a _F) holds, a value known only when the deck runs.
    pure logical function holds_unknown(v)
        type(value_t), intent(in) :: v
        holds_unknown = v%kind == VK_UNKNOWN
        if (holds_unknown .or. .not. allocated(v%tree)) return
        holds_unknown = any(v%tree%kind == VK_UNKNOWN)
    end function holds_unknown

    !> Error unless lo..hi positional arguments and only the keywords `keys`.
    subroutine arity(ctx, id, what, args, kwargs, lo, hi, keys, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id, lo, hi
        character(len=*), intent(in) :: what, keys
        type(value_t), intent(in) :: args(:), kwargs
        type(status_t), intent(inout) :: st
        if (size(args) < lo .or. size(args) > hi) then
            if (lo == hi) then
                call fail(st, ctx, id, what // '() takes ' // to_text(lo) // ' argument(s), ' &
                          // 'got ' // to_text(size(args)))
            else
                call fail(st, ctx, id, what // '() takes ' // to_text(lo) // ' to ' // &
                          to_text(hi) // ' arguments, got ' // to_text(size(args)))
            end if
            return
        end if
        call only_kwargs(ctx, id, what // '()', kwargs, keys, st)
    end subroutine arity

    !> Error unless v is a string (named `what` in the message).
    logical function want_text(ctx, id, v, what, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: v
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        want_text = v%kind == VK_STR
        if (.not. want_text) call fail(st, ctx, id, what // ' takes a string, got ' // &
                                       kind_label(v))
    end function want_text

end module deck_interp_base
