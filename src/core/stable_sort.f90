!> Stable sorting of items by a relation the caller defines: a bottom-up merge sort of the
!> indices 1..n, O(n log n), items that compare equal keeping their order. Tables (TRI),
!> functions and meshes (paths, repeated cells) sort through it.
module stable_sort
    use kinds, only: dp
    implicit none
    private

    !> What stable_order sorts: items 1..n that `compare` orders (-1, 0, 1 as item a sorts
    !> before, with or after item b). An extension holds the keys, so that no internal
    !> procedure is passed (an internal procedure as an argument needs a trampoline on an
    !> executable stack).
    type, abstract, public :: item_order_t
    contains
        procedure(compare_items), deferred :: compare
    end type item_order_t

    abstract interface
        integer function compare_items(self, a, b)
            import :: item_order_t
            class(item_order_t), intent(in) :: self
            integer, intent(in) :: a, b
        end function compare_items
    end interface

    !> Reals, increasing.
    type, extends(item_order_t) :: real_order_t
        real(dp), allocatable :: x(:)
    contains
        procedure :: compare => compare_reals
    end type real_order_t

    public :: stable_order, real_order

contains

    !> The permutation that sorts `x` increasingly, equal values in their order.
    function real_order(x) result(order)
        real(dp), intent(in) :: x(:)
        integer, allocatable :: order(:)
        type(real_order_t) :: reals
        reals%x = x
        call stable_order(size(x), reals, order)
    end function real_order

    !> The permutation of 1..n that sorts items by `relation`: a bottom-up merge sort,
    !> stable, O(n log n).
    subroutine stable_order(n, relation, order)
        integer, intent(in) :: n
        class(item_order_t), intent(in) :: relation
        integer, allocatable, intent(out) :: order(:)
        integer, allocatable :: work(:)
        integer :: width, lo, mid, hi, i, j, k
        allocate (order(n), work(n))
        order = [(i, i=1, n)]
        width = 1
        do while (width < n)
            lo = 1
            do while (lo <= n)
                mid = min(lo + width - 1, n)
                hi = min(lo + 2 * width - 1, n)
                if (mid < hi) then
                    i = lo; j = mid + 1; k = lo
                    do while (i <= mid .and. j <= hi)
                        if (relation%compare(order(j), order(i)) < 0) then  ! strictly before
                            work(k) = order(j); j = j + 1
                        else
                            work(k) = order(i); i = i + 1
                        end if
                        k = k + 1
                    end do
                    do while (i <= mid)
                        work(k) = order(i); i = i + 1; k = k + 1
                    end do
                    do while (j <= hi)
                        work(k) = order(j); j = j + 1; k = k + 1
                    end do
                    order(lo:hi) = work(lo:hi)
                end if
                lo = lo + 2 * width
            end do
            width = 2 * width
        end do
    end subroutine stable_order

    integer function compare_reals(self, a, b) result(c)
        class(real_order_t), intent(in) :: self
        integer, intent(in) :: a, b
        c = 0
        if (self%x(a) < self%x(b)) c = -1
        if (self%x(a) > self%x(b)) c = 1
    end function compare_reals

end module stable_sort
