!> Ordering the rows of a table (CALC_TABLE TRI, IMPR_TABLE TRI): stable_sort's merge sort of
!> row indices, O(n log n), on one or more key columns, as Code_Aster's Table.sort: rows
!> compare key after key; an absent cell sorts as the type's zero (0, 0.0 or the empty
!> text); texts compare character by character (a shorter text that is a prefix of a
!> longer one sorts first). DECROISSANT reverses the order of the keys; rows with equal
!> keys keep their order in both directions.
module table_sort
    use kinds, only: i8, dp
    use strings, only: string_t
    use table_concept, only: table_t, TABLE_INT, TABLE_REAL
    use stable_sort, only: item_order_t, stable_order, real_order
    implicit none
    private

    !> Rows of a table by key columns, DECROISSANT reversing.
    type, extends(item_order_t) :: row_order_t
        type(table_t), pointer :: t => null()
        integer, allocatable :: keys(:)
        logical :: descending = .false.
    contains
        procedure :: compare => compare_rows
    end type row_order_t

    !> Texts, as Python compares str.
    type, extends(item_order_t) :: text_order_t
        type(string_t), allocatable :: keys(:)
    contains
        procedure :: compare => compare_keys
    end type text_order_t

    public :: table_sorted_rows, compare_table_rows, compare_texts, stable_order, &
        real_order, text_order

contains

    !> The row indices of `t` in sorted order.
    !>  keys       : in, key columns (indices into t%columns), most significant first
    !>  descending : in, DECROISSANT
    !>  order      : out, (t%n_rows) row indices
    subroutine table_sorted_rows(t, keys, descending, order)
        type(table_t), intent(in), target :: t
        integer, intent(in) :: keys(:)
        logical, intent(in) :: descending
        integer, allocatable, intent(out) :: order(:)
        type(row_order_t) :: rows
        rows%t => t
        rows%keys = keys
        rows%descending = descending
        call stable_order(t%n_rows, rows, order)
    end subroutine table_sorted_rows

    !> The permutation that sorts `keys` (compare_texts), equal keys in their order.
    function text_order(keys) result(order)
        type(string_t), intent(in) :: keys(:)
        integer, allocatable :: order(:)
        type(text_order_t) :: texts
        texts%keys = keys
        call stable_order(size(keys), texts, order)
    end function text_order

    integer function compare_rows(self, a, b) result(c)
        class(row_order_t), intent(in) :: self
        integer, intent(in) :: a, b
        c = compare_table_rows(self%t, self%keys, a, b)
        if (self%descending) c = -c
    end function compare_rows

    integer function compare_keys(self, a, b) result(c)
        class(text_order_t), intent(in) :: self
        integer, intent(in) :: a, b
        c = compare_texts(self%keys(a)%s, self%keys(b)%s)
    end function compare_keys

    !> -1, 0 or 1 as row `a` sorts before, with or after row `b` on the key columns.
    pure integer function compare_table_rows(t, keys, a, b) result(c)
        type(table_t), intent(in) :: t
        integer, intent(in) :: keys(:), a, b
        integer :: k
        integer(i8) :: ia, ib
        real(dp) :: xa, xb
        c = 0
        do k = 1, size(keys)
            associate (col => t%columns(keys(k)))
                select case (col%kind)
                case (TABLE_INT)
                    ia = 0; ib = 0
                    if (col%present(a)) ia = col%ints(a)
                    if (col%present(b)) ib = col%ints(b)
                    if (ia < ib) c = -1
                    if (ia > ib) c = 1
                case (TABLE_REAL)
                    xa = 0.0_dp; xb = 0.0_dp
                    if (col%present(a)) xa = col%reals(a)
                    if (col%present(b)) xb = col%reals(b)
                    if (xa < xb) c = -1
                    if (xa > xb) c = 1
                case default
                    if (col%present(a) .and. col%present(b)) then
                        c = compare_texts(col%texts(a)%s, col%texts(b)%s)
                    else if (col%present(a)) then
                        c = compare_texts(col%texts(a)%s, '')
                    else if (col%present(b)) then
                        c = compare_texts('', col%texts(b)%s)
                    end if
                end select
            end associate
            if (c /= 0) return
        end do
    end function compare_table_rows

    !> -1, 0, 1: character codes compared in turn, then lengths (as Python compares str).
    pure integer function compare_texts(a, b) result(c)
        character(len=*), intent(in) :: a, b
        integer :: k
        c = 0
        do k = 1, min(len(a), len(b))
            if (iachar(a(k:k)) < iachar(b(k:k))) then
                c = -1; return
            else if (iachar(a(k:k)) > iachar(b(k:k))) then
                c = 1; return
            end if
        end do
        if (len(a) < len(b)) c = -1
        if (len(a) > len(b)) c = 1
    end function compare_texts

end module table_sort
