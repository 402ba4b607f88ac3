!> Ordering the rows of a table (CALC_TABLE TRI, IMPR_TABLE TRI): a stable merge sort of
!> row indices, O(n log n), on one or more key columns, as Code_Aster's Table.sort: rows
!> compare key after key; an absent cell sorts as the type's zero (0, 0.0 or the empty
!> text); texts compare character by character (a shorter text that is a prefix of a
!> longer one sorts first). DECROISSANT reverses the order of the keys; rows with equal
!> keys keep their order in both directions.
module table_sort
    use kinds, only: i8, dp
    use table_concept, only: table_t, TABLE_INT, TABLE_REAL
    implicit none
    private

    public :: table_sorted_rows, compare_table_rows, compare_texts

contains

    !> The row indices of `t` in sorted order.
    !>  keys       : in, key columns (indices into t%columns), most significant first
    !>  descending : in, DECROISSANT
    !>  order      : out, (t%n_rows) row indices
    subroutine table_sorted_rows(t, keys, descending, order)
        type(table_t), intent(in) :: t
        integer, intent(in) :: keys(:)
        logical, intent(in) :: descending
        integer, allocatable, intent(out) :: order(:)
        integer, allocatable :: work(:)
        integer :: r, width, lo, mid, hi
        allocate (order(t%n_rows), work(t%n_rows))
        order = [(r, r=1, t%n_rows)]
        width = 1
        do while (width < t%n_rows)          ! bottom-up merge sort: stable, n log n
            lo = 1
            do while (lo <= t%n_rows)
                mid = min(lo + width - 1, t%n_rows)
                hi = min(lo + 2 * width - 1, t%n_rows)
                if (mid < hi) call merge_runs(lo, mid, hi)
                lo = lo + 2 * width
            end do
            width = 2 * width
        end do
    contains
        subroutine merge_runs(first, middle, last)
            integer, intent(in) :: first, middle, last
            integer :: i, j, k, c
            i = first; j = middle + 1; k = first
            do while (i <= middle .and. j <= last)
                c = compare_table_rows(t, keys, order(j), order(i))
                if (descending) c = -c
                if (c < 0) then            ! strictly before: take from the right run
                    work(k) = order(j); j = j + 1
                else
                    work(k) = order(i); i = i + 1
                end if
                k = k + 1
            end do
            do while (i <= middle)
                work(k) = order(i); i = i + 1; k = k + 1
            end do
            do while (j <= last)
                work(k) = order(j); j = j + 1; k = k + 1
            end do
            order(first:last) = work(first:last)
        end subroutine merge_runs
    end subroutine table_sorted_rows

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
