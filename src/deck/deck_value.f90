!> Values of the deck language: integers, reals, booleans, strings, tuples/lists, factor
!> keyword occurrences (_F), concepts, `def` functions and built-in functions.
module deck_value
    use kinds, only: dp, i8
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    implicit none
    private

    integer, parameter, public :: VK_NONE = 0, VK_INT = 1, VK_REAL = 2, VK_BOOL = 3, &
        VK_STR = 4, VK_TUPLE = 5, VK_LIST = 6, VK_FACTOR = 7, VK_CONCEPT = 8, VK_DEF = 9, &
        VK_BUILTIN = 10, VK_UNKNOWN = 11, VK_DICT = 12, VK_MODULE = 13, VK_METHOD = 14, &
        VK_CO = 15

    !> One node of a flattened value tree (no recursive component: gfortran 12 shares the
    !> nested levels of recursive allocatable components on assignment, so composite values
    !> are stored flat). `nsub` is the number of descendants that follow it.
    type, public :: atom_t
        integer :: kind = VK_NONE
        integer(i8) :: i = 0
        real(dp) :: r = 0.0_dp
        character(len=:), allocatable :: s
        class(concept_t), pointer :: obj => null()
        integer :: line = 0, col = 0
        character(len=:), allocatable :: key        !< keyword name inside a _F
        integer :: key_line = 0, key_col = 0
        integer :: nsub = 0
    end type atom_t

    !> A deck value. `line`/`col` say where it was written (for messages).
    !>  VK_INT: i;  VK_REAL: r;  VK_BOOL: i (0/1);  VK_STR: s
    !>  VK_TUPLE/VK_FACTOR: items in `tree` (read them with nitems/item/unpack_value; a _F's
    !>  items carry their keyword names)
    !>  VK_LIST, VK_DICT: inside the interpreter, i > 0 = the container in the run's heap
    !>  (deck_heap: lists and dicts are shared, as Python's); handed to commands and methods
    !>  (and back), a list is flat like a tuple (i = 0, items in `tree`), a dict a VK_FACTOR
    !>  VK_MODULE: s = an imported module's name (math, or one parasol does not provide)
    !>  VK_METHOD: s = a method name bound to the object tree(1) (`f = L.append`)
    !>  VK_CO: s = the name of a concept a command is asked to make, CO('NAME')
    !>  VK_CONCEPT: obj (owned by the symbol table), s = its type name
    !>  VK_DEF: s = function name, i = its N_DEF node;  VK_BUILTIN: s = name
    !>  VK_UNKNOWN: a value known only when the deck runs (the check pass's stand-in for
    !>  what a method of a placeholder concept would give, e.g. a table's cell)
    type, public :: value_t
        integer :: kind = VK_NONE
        integer(i8) :: i = 0
        real(dp) :: r = 0.0_dp
        character(len=:), allocatable :: s
        class(concept_t), pointer :: obj => null()
        integer :: line = 0, col = 0
        type(atom_t), allocatable :: tree(:)     !< descendants, preorder
    end type value_t

    !> The items of a composite value, unpacked (keys only for _F).
    type, public :: value_list_t
        type(value_t), allocatable :: items(:)
        type(string_t), allocatable :: keys(:)
        integer, allocatable :: key_line(:), key_col(:)
    end type value_list_t

    public :: int_value, real_value, str_value, bool_value, kind_label, value_text, &
        is_number, as_real, nitems, item, unpack_value, pack_values, sequence_value, &
        append_value, append_string, values_of, joined

contains

    !> Constructors.
    pure function int_value(i) result(v)
        integer(i8), intent(in) :: i
        type(value_t) :: v
        v%kind = VK_INT; v%i = i
    end function int_value

    pure function real_value(r) result(v)
        real(dp), intent(in) :: r
        type(value_t) :: v
        v%kind = VK_REAL; v%r = r
    end function real_value

    pure function str_value(s) result(v)
        character(len=*), intent(in) :: s
        type(value_t) :: v
        v%kind = VK_STR; v%s = s
    end function str_value

    pure function bool_value(b) result(v)
        logical, intent(in) :: b
        type(value_t) :: v
        v%kind = VK_BOOL; v%i = merge(1_i8, 0_i8, b)
    end function bool_value

    !> Appends text to a list of strings. Element-wise copies: gfortran 12 corrupts
    !> `list = [list, string_t(x)]` when list is a component, so no array constructor of
    !> types with allocatable components is used on a growing list.
    pure subroutine append_string(list, text)
        type(string_t), allocatable, intent(inout) :: list(:)
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: bigger(:)
        integer :: k, n
        n = 0
        if (allocated(list)) n = size(list)
        allocate (bigger(n + 1))
        do k = 1, n
            bigger(k)%s = list(k)%s
        end do
        bigger(n + 1)%s = text
        call move_alloc(bigger, list)
    end subroutine append_string

    !> Appends v to a list of values (element-wise copies, see append_string).
    subroutine append_value(list, v)
        type(value_t), allocatable, intent(inout) :: list(:)
        type(value_t), intent(in) :: v
        type(value_t), allocatable :: bigger(:)
        integer :: k, n
        n = 0
        if (allocated(list)) n = size(list)
        allocate (bigger(n + 1))
        do k = 1, n
            bigger(k) = list(k)
        end do
        bigger(n + 1) = v
        call move_alloc(bigger, list)
    end subroutine append_value

    !> [a], [a, b] or [a, b, c], built item by item: gfortran 12 leaks the temporaries of
    !> array constructors of types with allocatable components, so no [a, b] of value_t.
    function values_of(a, b, c) result(list)
        type(value_t), intent(in) :: a
        type(value_t), intent(in), optional :: b, c
        type(value_t), allocatable :: list(:)
        integer :: n
        n = 1
        if (present(b)) n = 2
        if (present(c)) n = 3
        allocate (list(n))
        list(1) = a
        if (present(b)) list(2) = b
        if (present(c)) list(3) = c
    end function values_of

    !> The items of a followed by those of b (see values_of).
    function joined(a, b) result(list)
        type(value_t), intent(in) :: a(:), b(:)
        type(value_t), allocatable :: list(:)
        integer :: k
        allocate (list(size(a) + size(b)))
        do k = 1, size(a)
            list(k) = a(k)
        end do
        do k = 1, size(b)
            list(size(a) + k) = b(k)
        end do
    end function joined

    !> Number of items of a tuple, list or _F (0 for other values).
    pure integer function nitems(v)
        type(value_t), intent(in) :: v
        integer :: j
        nitems = 0
        if (.not. allocated(v%tree)) return
        j = 1
        do while (j <= size(v%tree))
            nitems = nitems + 1
            j = j + 1 + v%tree(j)%nsub
        end do
    end function nitems

    !> Item k of a composite value.
    function item(v, k) result(x)
        type(value_t), intent(in) :: v
        integer, intent(in) :: k
        type(value_t) :: x
        integer :: j, n
        j = 1; n = 0
        do while (j <= size(v%tree))
            n = n + 1
            if (n == k) then
                call from_atom(v%tree(j), x)
                x%tree = v%tree(j + 1:j + v%tree(j)%nsub)
                return
            end if
            j = j + 1 + v%tree(j)%nsub
        end do
    end function item

    !> All items of a composite value, with their keys (for a _F).
    function unpack_value(v) result(list)
        type(value_t), intent(in) :: v
        type(value_list_t) :: list
        integer :: j, n, k
        n = nitems(v)
        allocate (list%items(n), list%keys(n), list%key_line(n), list%key_col(n))
        j = 1
        do k = 1, n
            call from_atom(v%tree(j), list%items(k))
            list%items(k)%tree = v%tree(j + 1:j + v%tree(j)%nsub)
            list%keys(k)%s = ''
            if (allocated(v%tree(j)%key)) list%keys(k)%s = v%tree(j)%key
            list%key_line(k) = v%tree(j)%key_line
            list%key_col(k) = v%tree(j)%key_col
            j = j + 1 + v%tree(j)%nsub
        end do
    end function unpack_value

    !> A tuple/list/_F of kind `kind` holding list%items (keys used for a _F).
    function pack_values(kind, list) result(v)
        integer, intent(in) :: kind
        type(value_list_t), intent(in) :: list
        type(value_t) :: v
        integer :: k, j, total
        v%kind = kind
        total = 0
        do k = 1, size(list%items)
            total = total + 1
            if (allocated(list%items(k)%tree)) total = total + size(list%items(k)%tree)
        end do
        allocate (v%tree(total))
        j = 0
        do k = 1, size(list%items)
            j = j + 1
            call to_atom(list%items(k), v%tree(j))
            if (allocated(list%keys)) then
                v%tree(j)%key = list%keys(k)%s
                v%tree(j)%key_line = list%key_line(k)
                v%tree(j)%key_col = list%key_col(k)
            end if
            if (allocated(list%items(k)%tree)) then
                v%tree(j)%nsub = size(list%items(k)%tree)
                v%tree(j + 1:j + v%tree(j)%nsub) = list%items(k)%tree
                j = j + v%tree(j)%nsub
            end if
        end do
    end function pack_values

    !> A tuple or list of the given items.
    function sequence_value(kind, items) result(v)
        integer, intent(in) :: kind
        type(value_t), intent(in) :: items(:)
        type(value_t) :: v
        type(value_list_t) :: list
        list%items = items
        v = pack_values(kind, list)
    end function sequence_value

    subroutine from_atom(a, x)
        type(atom_t), intent(in) :: a
        type(value_t), intent(out) :: x
        x%kind = a%kind; x%i = a%i; x%r = a%r
        if (allocated(a%s)) x%s = a%s
        x%obj => a%obj
        x%line = a%line; x%col = a%col
    end subroutine from_atom

    subroutine to_atom(x, a)
        type(value_t), intent(in) :: x
        type(atom_t), intent(out) :: a
        a%kind = x%kind; a%i = x%i; a%r = x%r
        if (allocated(x%s)) a%s = x%s
        a%obj => x%obj
        a%line = x%line; a%col = x%col
    end subroutine to_atom

    !> True for integers, reals and booleans.
    elemental logical function is_number(v)
        type(value_t), intent(in) :: v
        is_number = v%kind == VK_INT .or. v%kind == VK_REAL .or. v%kind == VK_BOOL
    end function is_number

    !> A number as a real (0 for other values).
    elemental real(dp) function as_real(v)
        type(value_t), intent(in) :: v
        select case (v%kind)
        case (VK_INT, VK_BOOL)
            as_real = real(v%i, dp)
        case (VK_REAL)
            as_real = v%r
        case default
            as_real = 0.0_dp
        end select
    end function as_real

    !> What kind of value this is, in words, for messages ('a real', 'a string', 'a maillage').
    function kind_label(v) result(text)
        type(value_t), intent(in) :: v
        character(len=:), allocatable :: text
        select case (v%kind)
        case (VK_INT)
            text = 'an integer'
        case (VK_REAL)
            text = 'a real'
        case (VK_BOOL)
            text = 'a boolean'
        case (VK_STR)
            text = 'a string'
        case (VK_TUPLE)
            text = 'a tuple'
        case (VK_LIST)
            text = 'a list'
        case (VK_FACTOR)
            text = 'a _F(...) keyword group'
        case (VK_CONCEPT)
            text = 'a concept of type ' // v%s
        case (VK_DEF)
            text = 'the def function ' // v%s
        case (VK_BUILTIN)
            text = 'the built-in function ' // v%s
        case (VK_UNKNOWN)
            text = 'a value known when the deck runs'
        case (VK_DICT)
            text = 'a dict'
        case (VK_MODULE)
            text = 'the module ' // v%s
        case (VK_METHOD)
            text = 'the method ' // v%s
        case (VK_CO)
            text = 'CO(''' // v%s // ''')'
        case default
            text = 'None'
        end select
    end function kind_label

    !> Short text of a value for messages and the .mess echo.
    recursive function value_text(v) result(text)
        type(value_t), intent(in) :: v
        character(len=:), allocatable :: text
        integer :: k
        type(value_list_t) :: list
        select case (v%kind)
        case (VK_INT)
            text = to_text(v%i)
        case (VK_REAL)
            text = to_text(v%r)
        case (VK_BOOL)
            text = merge('True ', 'False', v%i /= 0)
            text = trim(text)
        case (VK_STR)
            text = "'" // v%s // "'"
        case (VK_TUPLE, VK_LIST, VK_FACTOR)
            text = '('
            list = unpack_value(v)
            do k = 1, size(list%items)
                if (k > 1) text = text // ', '
                if (v%kind == VK_FACTOR) text = text // list%keys(k)%s // '='
                if (k > 8) then
                    text = text // '...'
                    exit
                end if
                text = text // value_text(list%items(k))
            end do
            text = text // ')'
            if (v%kind == VK_FACTOR) text = '_F' // text
        case (VK_CONCEPT, VK_DEF, VK_BUILTIN, VK_UNKNOWN, VK_DICT, VK_MODULE, VK_METHOD, VK_CO)
            text = kind_label(v)
        case default
            text = 'None'
        end select
    end function value_text

end module deck_value
