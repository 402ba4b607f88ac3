!> The deck evaluator (deck_interpreter), the methods of its built-in types as Python 3
!> defines them: which type has which method, lists (append, extend, insert, pop, remove,
!> index, count, sort, reverse, copy, clear), dicts (keys, values, items, get, pop,
!> setdefault, update, copy, clear, popitem), tuples (index, count) and _F (read like a
!> dict); strings in deck_interp_strings.
submodule(deck_interpreter) deck_interp_types
    implicit none

    character(len=*), parameter :: STR_METHODS = ' capitalize center count endswith find ' // &
        'format index isalpha isdigit islower isspace isupper join ljust lower lstrip ' // &
        'partition replace rfind rindex rjust rpartition rsplit rstrip split splitlines ' // &
        'startswith strip swapcase title upper zfill '
    character(len=*), parameter :: LIST_METHODS = ' append extend insert pop remove index ' // &
        'count reverse sort copy clear '
    character(len=*), parameter :: DICT_METHODS = ' keys values items get pop setdefault ' // &
        'update copy clear popitem '
    character(len=*), parameter :: TUPLE_METHODS = ' index count '
    character(len=*), parameter :: FACTOR_METHODS = ' keys values items get copy '

contains

    module procedure type_has_method
        select case (kind)
        case (VK_STR)
            type_has_method = index(STR_METHODS, ' ' // name // ' ') > 0
        case (VK_LIST)
            type_has_method = index(LIST_METHODS, ' ' // name // ' ') > 0
        case (VK_DICT)
            type_has_method = index(DICT_METHODS, ' ' // name // ' ') > 0
        case (VK_TUPLE)
            type_has_method = index(TUPLE_METHODS, ' ' // name // ' ') > 0
        case (VK_FACTOR)
            type_has_method = index(FACTOR_METHODS, ' ' // name // ' ') > 0
        case default
            type_has_method = .false.
        end select
    end procedure type_has_method

    module procedure type_method
        character(len=:), allocatable :: methods
        if (.not. type_has_method(obj%kind, name)) then
            select case (obj%kind)
            case (VK_STR)
                methods = STR_METHODS
            case (VK_LIST)
                methods = LIST_METHODS
            case (VK_DICT)
                methods = DICT_METHODS
            case (VK_TUPLE)
                methods = TUPLE_METHODS
            case default
                methods = FACTOR_METHODS
            end select
            call fail(st, ctx, id, kind_label(obj) // ' has no method ' // name // &
                      ' (its methods:' // methods // ')'); return
        end if
        select case (obj%kind)
        case (VK_STR)
            call str_method(ctx, id, obj%s, name, args, kwargs, v, st)
        case (VK_LIST)
            call list_method(ctx, id, obj, name, args, kwargs, v, st, frame)
        case (VK_DICT)
            call dict_method(ctx, id, obj, name, args, kwargs, v, st)
        case (VK_TUPLE)
            call sequence_search(ctx, id, obj, name, args, v, st)
        case (VK_FACTOR)
            call factor_method(ctx, id, obj, name, args, v, st)
        end select
    end procedure type_method

    ! ---- lists ------------------------------------------------------------------------------

    recursive subroutine list_method(ctx, id, obj, name, args, kwargs, v, st, frame)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(frame_t), intent(inout), optional, target :: frame
        type(value_t), allocatable :: items(:)
        character(len=:), allocatable :: what
        integer :: n, k
        integer(i8) :: i
        what = 'list.' // name
        v%kind = VK_NONE
        n = ctx%heap%length(obj%i)
        select case (name)
        case ('append')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            call ctx%heap%append(obj%i, args(1))
            call check_heap(ctx, id, st)
        case ('extend')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            if (args(1)%kind == VK_UNKNOWN) return
            call iterate(ctx, id, args(1), items, st)
            if (st%failed()) return
            call count_built(ctx, id, int(size(items), i8), st)
            do k = 1, size(items)
                call ctx%heap%append(obj%i, items(k))
            end do
            call check_heap(ctx, id, st)
        case ('insert')
            call arity(ctx, id, what, args, kwargs, 2, 2, '', st)
            if (st%failed()) return
            if (args(1)%kind /= VK_INT .and. args(1)%kind /= VK_BOOL) then
                call fail(st, ctx, id, what // '() takes an integer position'); return
            end if
            i = args(1)%i
            if (i < 0) i = max(0_i8, i + n)
            i = min(i, int(n, i8))
            call ctx%heap%insert(obj%i, int(i) + 1, args(2))
            call check_heap(ctx, id, st)
        case ('pop')
            call arity(ctx, id, what, args, kwargs, 0, 1, '', st)
            if (st%failed()) return
            if (n == 0) then
                call fail(st, ctx, id, 'pop from an empty list'); return
            end if
            i = -1
            if (size(args) == 1) then
                if (args(1)%kind /= VK_INT .and. args(1)%kind /= VK_BOOL) then
                    call fail(st, ctx, id, what // '() takes an integer position'); return
                end if
                i = args(1)%i
            end if
            call get_item(ctx, id, obj, int_value(i), v, st)
            if (st%failed()) return
            if (i < 0) i = i + n
            call ctx%heap%remove_at(obj%i, int(i) + 1)
        case ('remove')
            call arity(ctx, id, what, args, kwargs, 1, 1, '', st)
            if (st%failed()) return
            do k = 1, n
                if (values_equal(ctx, ctx%heap%get(obj%i, k), args(1))) then
                    call ctx%heap%remove_at(obj%i, k)
                    return
                end if
            end do
            call fail(st, ctx, id, what // '(x): x not in the list (x = ' // &
                      text_of(ctx, args(1), .true.) // ')')
        case ('index', 'count')
            call sequence_search(ctx, id, obj, name, args, v, st)
        case ('reverse')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            items = ctx%heap%items_of(obj%i)
            call ctx%heap%set_items(obj%i, items(size(items):1:-1))
        case ('sort')
            call arity(ctx, id, what, args, kwargs, 0, 0, 'key reverse', st)
            if (st%failed()) return
            items = ctx%heap%items_of(obj%i)
            call sort_items(ctx, id, items, kwargs, st, frame)
            if (st%failed()) return
            call ctx%heap%set_items(obj%i, items)
        case ('copy')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            call count_built(ctx, id, int(n, i8), st)
            v = new_list(ctx, ctx%heap%items_of(obj%i))
            call check_heap(ctx, id, st)
        case ('clear')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            call ctx%heap%clear(obj%i)
        end select
    end subroutine list_method

    !> index(x) and count(x) of a list or a tuple.
    recursive subroutine sequence_search(ctx, id, obj, name, args, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: items(:)
        integer :: k, hits
        if (size(args) /= 1) then
            call fail(st, ctx, id, name // '() takes 1 argument, got ' // to_text(size(args)))
            return
        end if
        if (args(1)%kind == VK_UNKNOWN) then
            v = args(1); return
        end if
        call iterate(ctx, id, obj, items, st)
        if (st%failed()) return
        hits = 0
        do k = 1, size(items)
            if (.not. values_equal(ctx, items(k), args(1))) cycle
            if (name == 'index') then
                v = int_value(int(k - 1, i8)); return
            end if
            hits = hits + 1
        end do
        if (name == 'index') then
            call fail(st, ctx, id, text_of(ctx, args(1), .true.) // ' is not in the ' // &
                      merge('list ', 'tuple', obj%kind == VK_LIST)); return
        end if
        v = int_value(int(hits, i8))
    end subroutine sequence_search

    ! ---- dicts ------------------------------------------------------------------------------

    recursive subroutine dict_method(ctx, id, obj, name, args, kwargs, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:), kwargs
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_t), allocatable :: keys(:), vals(:), pairs(:), items(:), pair(:)
        type(value_list_t) :: kw
        character(len=:), allocatable :: what
        integer :: k, n
        what = 'dict.' // name
        v%kind = VK_NONE
        n = ctx%heap%length(obj%i)
        select case (name)
        case ('keys', 'values', 'items')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            keys = ctx%heap%keys_of(obj%i)
            vals = ctx%heap%items_of(obj%i)
            if (name == 'keys') then
                v = new_list(ctx, keys)
            else if (name == 'values') then
                v = new_list(ctx, vals)
            else
                allocate (pairs(n))
                do k = 1, n
                    pairs(k) = sequence_value(VK_TUPLE, values_of(keys(k), vals(k)))
                end do
                v = new_list(ctx, pairs)
            end if
            call count_built(ctx, id, int(n, i8), st)
            call check_heap(ctx, id, st)
        case ('get', 'pop', 'setdefault')
            call arity(ctx, id, what, args, kwargs, 1, 2, '', st)
            if (st%failed()) return
            if (args(1)%kind == VK_UNKNOWN) then
                v = args(1); return
            end if
            if (.not. hashable_key(args(1))) return
            k = ctx%heap%dict_find(obj%i, args(1))
            if (k > 0) then
                v = ctx%heap%get(obj%i, k)
                if (name == 'pop') call ctx%heap%dict_delete(obj%i, k)
                return
            end if
            if (size(args) == 2) v = args(2)
            if (name == 'pop' .and. size(args) == 1) then
                call get_item(ctx, id, obj, args(1), v, st)     ! the KeyError message
                return
            end if
            if (name == 'setdefault') then
                call ctx%heap%dict_set(obj%i, args(1), v)
                call check_heap(ctx, id, st)
            end if
        case ('update')
            call arity(ctx, id, what, args, kwargs, 0, 1, '*', st)
            if (st%failed()) return
            if (size(args) == 1) then
                select case (args(1)%kind)
                case (VK_DICT)
                    keys = ctx%heap%keys_of(args(1)%i)
                    vals = ctx%heap%items_of(args(1)%i)
                    do k = 1, size(keys)
                        call ctx%heap%dict_set(obj%i, keys(k), vals(k))
                    end do
                case (VK_FACTOR)
                    kw = unpack_value(args(1))
                    do k = 1, size(kw%items)
                        call ctx%heap%dict_set(obj%i, str_value(kw%keys(k)%s), kw%items(k))
                    end do
                case default
                    call iterate(ctx, id, args(1), items, st)
                    if (st%failed()) return
                    do k = 1, size(items)
                        call iterate(ctx, id, items(k), pair, st)
                        if (st%failed()) return
                        if (size(pair) /= 2) then
                            call fail(st, ctx, id, what // '() takes pairs (KEY, VALUE)'); return
                        end if
                        if (.not. hashable_key(pair(1))) return
                        call ctx%heap%dict_set(obj%i, pair(1), pair(2))
                    end do
                end select
            end if
            if (nitems(kwargs) > 0) then
                kw = unpack_value(kwargs)
                do k = 1, size(kw%items)
                    call ctx%heap%dict_set(obj%i, str_value(kw%keys(k)%s), kw%items(k))
                end do
            end if
            call check_heap(ctx, id, st)
        case ('copy')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            v = ctx%heap%new_dict()
            keys = ctx%heap%keys_of(obj%i)
            vals = ctx%heap%items_of(obj%i)
            do k = 1, size(keys)
                call ctx%heap%dict_set(v%i, keys(k), vals(k))
            end do
            call check_heap(ctx, id, st)
        case ('clear')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            call ctx%heap%clear(obj%i)
        case ('popitem')
            call arity(ctx, id, what, args, kwargs, 0, 0, '', st)
            if (st%failed()) return
            if (n == 0) then
                call fail(st, ctx, id, 'popitem(): the dict is empty'); return
            end if
            v = sequence_value(VK_TUPLE, values_of(ctx%heap%key_at(obj%i, n), ctx%heap%get(obj%i, n)))
            call ctx%heap%dict_delete(obj%i, n)
        end select
    contains
        logical function hashable_key(key)
            use deck_heap, only: hashable
            type(value_t), intent(in) :: key
            hashable_key = hashable(key)
            if (.not. hashable_key) call fail(st, ctx, id, kind_label(key) // &
                ' cannot be a dict key (keys are numbers, strings, tuples of them...)')
        end function hashable_key
    end subroutine dict_method

    !> keys(), values(), items(), get(), copy() of a _F (Code_Aster's _F is a dict).
    recursive subroutine factor_method(ctx, id, obj, name, args, v, st)
        type(run_context_t), intent(inout) :: ctx
        integer, intent(in) :: id
        type(value_t), intent(in) :: obj
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: args(:)
        type(value_t), intent(out) :: v
        type(status_t), intent(inout) :: st
        type(value_list_t) :: list
        type(value_t), allocatable :: out(:)
        integer :: k, n
        list = unpack_value(obj)
        n = nitems(obj)
        select case (name)
        case ('keys', 'values', 'items')
            allocate (out(n))
            do k = 1, n
                if (name == 'keys') out(k) = str_value(list%keys(k)%s)
                if (name == 'values') out(k) = list%items(k)
                if (name == 'items') out(k) = sequence_value(VK_TUPLE, &
                    values_of(str_value(list%keys(k)%s), list%items(k)))
            end do
            v = new_list(ctx, out)
            call check_heap(ctx, id, st)
        case ('get')
            if (size(args) < 1 .or. size(args) > 2) then
                call fail(st, ctx, id, 'get() takes 1 or 2 arguments'); return
            end if
            v%kind = VK_NONE
            if (size(args) == 2) v = args(2)
            if (args(1)%kind /= VK_STR) return
            do k = 1, n
                if (list%keys(k)%s == args(1)%s) v = list%items(k)
            end do
        case ('copy')
            v = ctx%heap%new_dict()
            do k = 1, n
                call ctx%heap%dict_set(v%i, str_value(list%keys(k)%s), list%items(k))
            end do
            call check_heap(ctx, id, st)
        end select
    end subroutine factor_method

end submodule deck_interp_types
