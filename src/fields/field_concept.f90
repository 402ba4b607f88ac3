!> The field concepts of the deck (CREA_CHAMP's results): a field (field_types) and the
!> concepts it lives on. Code_Aster's catalog types, by location:
!>   NOEU       -> cham_no_sdaster
!>   ELGA, ELNO, ELEM -> cham_elem
!>   CART       -> carte_sdaster
!> `support` is the concept the field's node and cell numbers refer to: a maillage, or a
!> modele (whose copy of the mesh is the same numbering); `model` the modele of a cham_elem
!> (its elements decide the points). Both are owned by the run context, which frees
!> concepts only at the end of a run (DETRUIRE forgets a name, the concept stays), so the
!> pointers stay valid while the field does.
module field_concept
    use kinds, only: i4
    use strings, only: to_text
    use deck_concept, only: concept_t, concept_display_name
    use field_types, only: field_t, FIELD_NOEU, FIELD_CART, FIELD_NONE, field_type_cham
    implicit none
    private

    type, extends(concept_t), public :: field_concept_t
        type(field_t) :: field
        class(concept_t), pointer :: support => null()   !< maillage or modele
        class(concept_t), pointer :: model => null()     !< modele (cham_elem), if known
    contains
        procedure :: type_name => field_concept_type_name
        procedure :: summary => field_concept_summary
    end type field_concept_t

    public :: field_concept_type_of

contains

    !> The catalog type of a field of `location` (FIELD_*).
    pure function field_concept_type_of(location) result(name)
        integer(i4), intent(in) :: location
        character(len=:), allocatable :: name
        select case (location)
        case (FIELD_NOEU)
            name = 'cham_no_sdaster'
        case (FIELD_CART)
            name = 'carte_sdaster'
        case (FIELD_NONE)
            name = 'cham_gd_sdaster'
        case default
            name = 'cham_elem'
        end select
    end function field_concept_type_of

    function field_concept_type_name(self) result(name)
        class(field_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = field_concept_type_of(self%field%location)
    end function field_concept_type_name

    !> "CH (cham_no_sdaster): NOEU_DEPL_R, 3 components on 120 nodes".
    function field_concept_summary(self) result(text)
        class(field_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        integer(i4) :: n_cmp
        n_cmp = 0
        if (allocated(self%field%components)) n_cmp = size(self%field%components, kind=i4)
        text = concept_display_name(self) // ' (' // self%type_name() // '): ' // &
            field_type_cham(self%field) // ', ' // to_text(n_cmp) // ' component(s) on '
        if (self%field%location == FIELD_NOEU) then
            text = text // to_text(count(any(self%field%node_has, dim=1))) // ' node(s)'
        else if (allocated(self%field%n_points)) then
            text = text // to_text(count(self%field%n_points > 0)) // ' cell(s)'
        else
            text = text // 'nothing'
        end if
    end function field_concept_summary

end module field_concept
