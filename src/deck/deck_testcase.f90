!> Code_Aster's test helper `CA.TestCase()` (code_aster/Utilities/Tester.py): an object whose
!> assert methods never stop the deck but write one OK or NOOK line each, counted with the
!> TEST_RESU lines. The deck interpreter runs its methods (deck_interp_testcase); this is
!> the object itself.
module deck_testcase
    use deck_concept, only: concept_t
    implicit none
    private

    !> One `CA.TestCase()`: its counts (printSummary) and whether the last assert failed
    !> (`test.last_failed`). silent=True writes nothing (Code_Aster's silent mode).
    type, extends(concept_t), public :: testcase_t
        integer :: passed = 0, failure = 0
        logical :: last_ok = .true.
        logical :: silent = .false.
    contains
        procedure :: type_name => testcase_type_name
        procedure :: summary => testcase_summary
    end type testcase_t

contains

    function testcase_type_name(self) result(name)
        class(testcase_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'TestCase'
        if (.false.) name = self%name
    end function testcase_type_name

    function testcase_summary(self) result(text)
        class(testcase_t), intent(in) :: self
        character(len=:), allocatable :: text
        character(len=24) :: a, b
        write (a, '(i0)') self%passed
        write (b, '(i0)') self%failure
        text = 'TestCase (' // trim(a) // ' passed, ' // trim(b) // ' in failure)'
    end function testcase_summary

end module deck_testcase
