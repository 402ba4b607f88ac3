!> Materials (DEFI_MATERIAU) and their assignment to cells (AFFE_MATERIAU).
!>
!> A material holds the behaviours parasol uses: ELAS (E, NU, RHO optional) and
!> DIS_CONTACT (the unilateral spring data of DIS_CHOC). Optional values carry presence
!> flags; defaults are Code_Aster's (RIGI_TAN = DIST_1 = DIST_2 = COULOMB = 0).
module model_material
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text
    use mesh_types, only: mesh_t, cell_label
    use model_types, only: model_t, is_plate, is_plane_solid, ELEMENT_NAMES
    implicit none
    private

    !> ELAS behaviour (isotropic linear elasticity).
    type, public :: elas_t
        real(dp) :: e = 0.0_dp          !< Young's modulus
        real(dp) :: nu = 0.0_dp         !< Poisson's ratio
        logical :: has_rho = .false.
        real(dp) :: rho = 0.0_dp        !< density, if has_rho
    end type elas_t

    !> DIS_CONTACT behaviour (DIS_CHOC springs). Code_Aster defaults in the initialisers.
    type, public :: dis_contact_t
        logical :: has_rigi_nor = .false.
        real(dp) :: rigi_nor = 0.0_dp   !< normal stiffness; absent: the discrete's own
        real(dp) :: rigi_tan = 0.0_dp   !< tangential stiffness
        real(dp) :: dist_1 = 0.0_dp     !< gap reduction at node 1
        real(dp) :: dist_2 = 0.0_dp     !< gap reduction at node 2
        logical :: has_jeu = .false.
        real(dp) :: jeu = 0.0_dp        !< gap (POI1 discretes), if has_jeu
        real(dp) :: coulomb = 0.0_dp    !< friction coefficient
        real(dp) :: amor_nor = 0.0_dp   !< normal damping (accepted; statics ignore it)
        real(dp) :: amor_tan = 0.0_dp   !< tangential damping (accepted; statics ignore it)
    end type dis_contact_t

    !> One material (a DEFI_MATERIAU result).
    type, public :: material_t
        character(len=:), allocatable :: name   !< deck name, for messages
        logical :: has_elas = .false.
        type(elas_t) :: elas
        logical :: has_dis_contact = .false.
        type(dis_contact_t) :: dis_contact
    end type material_t

    !> Materials assigned to cells (an AFFE_MATERIAU result): cell_material(c) indexes
    !> materials(:), 0 = none.
    type, public :: material_field_t
        type(material_t), allocatable :: materials(:)
        integer(i4), allocatable :: cell_material(:)
    end type material_field_t

    public :: material_field_init, assign_material, check_materials, material_of_cell

contains

    !> An empty material field over the cells of `mesh`.
    subroutine material_field_init(field, mesh)
        type(material_field_t), intent(out) :: field
        type(mesh_t), intent(in) :: mesh
        allocate (field%materials(0))
        allocate (field%cell_material(mesh%n_cells), source=0_i4)
    end subroutine material_field_init

    !> Assigns `material` to `cells` (later assignments override earlier ones). The material
    !> is copied into the field once per call.
    subroutine assign_material(field, cells, material)
        type(material_field_t), intent(inout) :: field
        integer(i4), intent(in) :: cells(:)
        type(material_t), intent(in) :: material
        field%materials = [field%materials, material]
        field%cell_material(cells) = size(field%materials, kind=i4)
    end subroutine assign_material

    !> Index in field%materials of the material of cell c (0 if none).
    integer(i4) function material_of_cell(field, c)
        type(material_field_t), intent(in) :: field
        integer(i4), intent(in) :: c
        material_of_cell = field%cell_material(c)
    end function material_of_cell

    !> Checks every modelled cell has the data its element needs: plates and plane solids
    !> need ELAS with E > 0 and -1 < NU < 0.5; discretes and load edges need nothing (ELAS
    !> on springs is accepted and unused, as in Code_Aster).
    !>  st : out, STATUS_MODEL_ERROR naming the first cell (and its group) that lacks data
    subroutine check_materials(field, model, mesh, st)
        type(material_field_t), intent(in) :: field
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        type(status_t), intent(out) :: st
        integer(i4) :: c, m
        do c = 1, model%n_cells
            if (.not. (is_plate(model%element(c)) .or. is_plane_solid(model%element(c)))) cycle
            m = field%cell_material(c)
            if (m == 0) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ' (' // &
                    trim(ELEMENT_NAMES(model%element(c))) // ') has no material: ' // &
                    'AFFE_MATERIAU must give it one with ELAS')
                return
            end if
            associate (mat => field%materials(m))
                if (.not. mat%has_elas) then
                    call set_error(st, STATUS_MODEL_ERROR, 'material ' // label(mat) // ' on ' &
                        // cell_label(mesh, c) // ' has no ELAS: its ' // &
                        trim(ELEMENT_NAMES(model%element(c))) // ' element needs E and NU')
                    return
                end if
                if (mat%elas%e <= 0.0_dp .or. mat%elas%nu <= -1.0_dp .or. &
                    mat%elas%nu >= 0.5_dp) then
                    call set_error(st, STATUS_MODEL_ERROR, 'material ' // label(mat) // ' on ' &
                        // cell_label(mesh, c) // ': ELAS needs E > 0 and -1 < NU < 0.5 (E = ' &
                        // to_text(mat%elas%e) // ', NU = ' // to_text(mat%elas%nu) // ')')
                    return
                end if
            end associate
        end do
    end subroutine check_materials

    pure function label(mat) result(text)
        type(material_t), intent(in) :: mat
        character(len=:), allocatable :: text
        text = '(unnamed)'
        if (allocated(mat%name)) text = mat%name
    end function label

end module model_material
