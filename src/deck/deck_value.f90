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
        VK_BUILTIN = 10

    !> A deck value. `line`/`col` say where it was written (for messages).
    !>  VK_INT: i;  VK_REAL: r;  VK_BOOL: i (0/1);  VK_STR: s;  VK_TUPLE/VK_LIST: items
    !>  VK_FACTOR: keys(k) = items(k), written at key_line(k), key_col(k)
    !>  VK_CONCEPT: obj (owned by the symbol table), s = its type name
    !>  VK_DEF: s = function name, i = its N_DEF node;  VK_BUILTIN: s = name
    type, public :: value_t
        integer :: kind = VK_NONE
        integer(i8) :: i = 0
        real(dp) :: r = 0.0_dp
        character(len=:), allocatable :: s
        type(value_t), allocatable :: items(:)
        type(string_t), allocatable :: keys(:)
        integer, allocatable :: key_line(:), key_col(:)
        class(concept_t), pointer :: obj => null()
        integer :: line = 0, col = 0
    end type value_t

    public :: int_value, real_value, str_value, bool_value, kind_label, value_text, &
        is_number, as_real, truth

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

    !> Python truth value.
    logical function truth(v)
        type(value_t), intent(in) :: v
        select case (v%kind)
        case (VK_INT, VK_BOOL)
            truth = v%i /= 0
        case (VK_REAL)
            truth = v%r > 0.0_dp .or. v%r < 0.0_dp
        case (VK_STR)
            truth = len(v%s) > 0
        case (VK_TUPLE, VK_LIST)
            truth = size(v%items) > 0
        case (VK_NONE)
            truth = .false.
        case default
            truth = .true.
        end select
    end function truth

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
        case default
            text = 'None'
        end select
    end function kind_label

    !> Short text of a value for messages and the .mess echo.
    recursive function value_text(v) result(text)
        type(value_t), intent(in) :: v
        character(len=:), allocatable :: text
        integer :: k
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
            do k = 1, size(v%items)
                if (k > 1) text = text // ', '
                if (v%kind == VK_FACTOR) text = text // v%keys(k)%s // '='
                if (k > 8) then
                    text = text // '...'
                    exit
                end if
                text = text // value_text(v%items(k))
            end do
            text = text // ')'
            if (v%kind == VK_FACTOR) text = '_F' // text
        case (VK_CONCEPT, VK_DEF, VK_BUILTIN)
            text = kind_label(v)
        case default
            text = 'None'
        end select
    end function value_text

end module deck_value
