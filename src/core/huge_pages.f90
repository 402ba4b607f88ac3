!> Large arrays advised for transparent huge pages (Linux madvise MADV_HUGEPAGE, honoured
!> when /sys/kernel/mm/transparent_hugepage/enabled is "madvise" or "always"): the arrays of
!> a large analysis (the assembled matrix, the element caches) are touched first page by
!> page, and with 4 kB pages each first touch is a page fault; 2 MB pages cut their number
!> 512-fold and the TLB misses of the sweeps over them (doc/performance.md, "Contact
!> Newton": page faults cost ~20 % of a 16 x 64 run on the project's VM). The advice only
!> covers the 2 MB-aligned interior of an array and is dropped silently where the system
!> refuses it: results never depend on it.
module huge_pages
    use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_size_t, c_intptr_t, c_loc
    use kinds, only: dp, i4, i8
    implicit none
    private

    !> Arrays smaller than this are left alone (glibc serves them from its heap anyway).
    integer(i8), parameter :: HUGE_PAGE_MIN_BYTES = 4_i8 * 1024_i8 * 1024_i8
    integer(i8), parameter :: HUGE_PAGE_BYTES = 2_i8 * 1024_i8 * 1024_i8
    !> <sys/mman.h> (Linux): MADV_HUGEPAGE.
    integer(c_int), parameter :: MADV_HUGEPAGE = 14

    interface
        function c_madvise(address, length, advice) result(rc) bind(c, name='madvise')
            import :: c_ptr, c_size_t, c_int
            type(c_ptr), value :: address
            integer(c_size_t), value :: length
            integer(c_int), value :: advice
            integer(c_int) :: rc
        end function c_madvise
    end interface

    !> Advises an allocated, contiguous array for huge pages (no-op below
    !> HUGE_PAGE_MIN_BYTES or where madvise fails).
    interface advise_huge_pages
        module procedure advise_real, advise_real2, advise_int4
    end interface advise_huge_pages

    public :: advise_huge_pages

contains

    subroutine advise_real(x)
        real(dp), intent(in), contiguous, target :: x(:)
        if (size(x, kind=i8) * 8_i8 < HUGE_PAGE_MIN_BYTES) return
        call advise_range(c_loc(x), size(x, kind=i8) * 8_i8)
    end subroutine advise_real

    subroutine advise_real2(x)
        real(dp), intent(in), contiguous, target :: x(:, :)
        if (size(x, kind=i8) * 8_i8 < HUGE_PAGE_MIN_BYTES) return
        call advise_range(c_loc(x), size(x, kind=i8) * 8_i8)
    end subroutine advise_real2

    subroutine advise_int4(x)
        integer(i4), intent(in), contiguous, target :: x(:)
        if (size(x, kind=i8) * 4_i8 < HUGE_PAGE_MIN_BYTES) return
        call advise_range(c_loc(x), size(x, kind=i8) * 4_i8)
    end subroutine advise_int4

    !> madvise on the huge-page-aligned part of [address, address + bytes).
    subroutine advise_range(address, bytes)
        type(c_ptr), intent(in) :: address
        integer(i8), intent(in) :: bytes
        integer(c_intptr_t) :: first, last, start
        type(c_ptr) :: aligned
        integer(c_int) :: rc
        first = transfer(address, first)
        last = first + int(bytes, c_intptr_t)
        start = ((first + int(HUGE_PAGE_BYTES, c_intptr_t) - 1) / &
            int(HUGE_PAGE_BYTES, c_intptr_t)) * int(HUGE_PAGE_BYTES, c_intptr_t)
        last = (last / int(HUGE_PAGE_BYTES, c_intptr_t)) * int(HUGE_PAGE_BYTES, c_intptr_t)
        if (last <= start) return
        aligned = transfer(start, aligned)
        rc = c_madvise(aligned, int(last - start, c_size_t), MADV_HUGEPAGE)
        if (rc /= 0) return           ! refused (no THP, not Linux): 4 kB pages, same results
    end subroutine advise_range

end module huge_pages
